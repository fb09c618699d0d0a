// The image sizes accepted anywhere: a camera's, a message's, a
// rectification's. A calibration and the messages that carry images check
// against the same bound.
#pragma once

#include <cstdint>

namespace ws {

// Whether an image (or a camera) of this size is one we accept anywhere: at
// most 65536 pixels a side and 2^28 pixels in all.
inline bool ImageSizeAcceptable(int64_t width, int64_t height) {
  constexpr int64_t kMaxSide = 1 << 16;
  constexpr int64_t kMaxPixels = int64_t(1) << 28;
  return width > 0 && height > 0 && width <= kMaxSide && height <= kMaxSide &&
         width * height <= kMaxPixels;
}

}  // namespace ws
