// Big-endian integers in bytes (LCM log headers, JPEG and PNG headers).
#pragma once

#include <cstdint>
#include <string>

namespace ws {

// The `n`-byte big-endian unsigned integer at `p` (n <= 8).
inline uint64_t BigEndian(const unsigned char* p, int n) {
  uint64_t v = 0;
  for (int i = 0; i < n; ++i) v = (v << 8) | p[i];
  return v;
}

// Appends the `n` low bytes of `v` to `out`, most significant first.
inline void AppendBigEndian(uint64_t v, int n, std::string* out) {
  for (int i = n - 1; i >= 0; --i) out->push_back(char((v >> (8 * i)) & 0xFF));
}

}  // namespace ws
