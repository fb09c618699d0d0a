// Base64 (RFC 4648, with padding): images and point arrays inside the page's JSON events.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace ws::view {

std::string Base64(const uint8_t* data, size_t size);

}  // namespace ws::view
