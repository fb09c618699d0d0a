// Reading big-endian integers out of bytes (LCM log headers, JPEG and PNG
// headers).
#pragma once

#include <cstdint>

namespace ws {

// The `n`-byte big-endian unsigned integer at `p` (n <= 8).
inline uint64_t BigEndian(const unsigned char* p, int n) {
  uint64_t v = 0;
  for (int i = 0; i < n; ++i) v = (v << 8) | p[i];
  return v;
}

}  // namespace ws
