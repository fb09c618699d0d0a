// Counting frames that never arrived from the gaps in a camera's frame ids.
#pragma once

#include <cstdint>

namespace ws {

// Frames missed between two consecutive frame ids. GigE Vision 1.x ids are
// 16 bits and wrap from 65535 to 1 (0 is never used); a repeated id, or one
// that goes backwards on a wider counter, counts nothing.
inline uint64_t FramesSkipped(uint64_t previous, uint64_t current) {
  constexpr uint64_t kLastShortId = 0xFFFF;
  if (current > previous) return current - previous - 1;
  if (current == previous || current == 0 || previous > kLastShortId) return 0;
  return (kLastShortId - previous) + (current - 1);
}

}  // namespace ws
