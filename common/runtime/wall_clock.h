// The wall clock, in the unit of every message's utime.
#pragma once

#include <chrono>
#include <cstdint>

namespace ws {

// Microseconds since the epoch.
inline int64_t WallMicros() {
  return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

}  // namespace ws
