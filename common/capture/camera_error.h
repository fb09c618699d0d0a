// The error every part of capture/ throws: a camera that cannot be opened or
// configured, a fake camera that cannot serve, an image that does not fit.
#pragma once

#include <stdexcept>

namespace ws {

struct CameraError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace ws
