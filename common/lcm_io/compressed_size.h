// The size a JPEG or PNG payload says it has, read from its header (JPEG's
// SOFn segment, PNG's IHDR chunk) without decoding it. ValidateImage checks
// it against the message's width and height: a 700-byte JPEG claiming tens
// of megapixels took a second to decode (a fuzz finding).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>

namespace ws {

struct PixelSize {
  int64_t width = 0, height = 0;
};

// nullopt when the bytes are neither a JPEG with a frame header before its
// first scan nor a PNG with its IHDR chunk.
std::optional<PixelSize> CompressedImageSize(const uint8_t* data, size_t size);

}  // namespace ws
