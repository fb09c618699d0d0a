#include "lcm_io/compressed_size.h"

#include <cstring>

#include "lcm_io/big_endian.h"

namespace ws {
namespace {

std::optional<PixelSize> PngSize(const uint8_t* data, size_t size) {
  static const uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  // The signature, then IHDR first: its length (13), type, width, height, ...
  constexpr size_t kIhdrLength = 13, kIhdrEnd = 8 + 4 + 4 + kIhdrLength;
  if (size < kIhdrEnd || std::memcmp(data, kSignature, 8) != 0 || BigEndian(data + 8, 4) != kIhdrLength ||
      std::memcmp(data + 12, "IHDR", 4) != 0)
    return std::nullopt;
  return PixelSize{int64_t(BigEndian(data + 16, 4)), int64_t(BigEndian(data + 20, 4))};
}

// Walks the JPEG's marker segments up to the first frame header (SOF0..SOF15
// but DHT C4, JPG C8 and DAC CC); a scan (SOS) or the end (EOI) before it
// means none, and so does a segment whose length runs past the payload's end.
std::optional<PixelSize> JpegSize(const uint8_t* data, size_t size) {
  if (size < 4 || data[0] != 0xff || data[1] != 0xd8) return std::nullopt;
  size_t i = 2;
  while (i + 4 <= size) {
    if (data[i] != 0xff) return std::nullopt;
    const uint8_t marker = data[i + 1];
    if (marker == 0xff) {  // fill byte
      ++i;
      continue;
    }
    if (marker == 0x01 || (marker >= 0xd0 && marker <= 0xd8)) {  // no length
      i += 2;
      continue;
    }
    const size_t length = BigEndian(data + i + 2, 2);  // its own 2 bytes included
    if (length < 2 || i + 2 + length > size || marker == 0xda || marker == 0xd9) return std::nullopt;
    if (marker >= 0xc0 && marker <= 0xcf && marker != 0xc4 && marker != 0xc8 && marker != 0xcc) {
      if (length < 8) return std::nullopt;  // P, Y, X, Nf at least
      return PixelSize{int64_t(BigEndian(data + i + 7, 2)), int64_t(BigEndian(data + i + 5, 2))};
    }
    i += 2 + length;
  }
  return std::nullopt;
}

}  // namespace

std::optional<PixelSize> CompressedImageSize(const uint8_t* data, size_t size) {
  if (auto png = PngSize(data, size)) return png;
  return JpegSize(data, size);
}

}  // namespace ws
