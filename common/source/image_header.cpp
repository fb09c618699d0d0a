#include "source/image_header.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstring>
#include <limits>
#include <vector>

#include "lcm_io/compressed_size.h"

namespace ws {
namespace {

// Bytes read at checked offsets: every read inside [0, size) or none.
class Bytes {
 public:
  Bytes(const uint8_t* data, size_t size) : data_(data), size_(size) {}
  bool Has(size_t at, size_t n) const { return at <= size_ && n <= size_ - at; }
  uint32_t Be(size_t at, int n) const { return Read(at, n, true); }
  uint32_t Le(size_t at, int n) const { return Read(at, n, false); }
  bool Starts(const char* magic) const {
    const size_t n = std::strlen(magic);
    return Has(0, n) && std::memcmp(data_, magic, n) == 0;
  }
  uint8_t At(size_t at) const { return data_[at]; }
  size_t size() const { return size_; }

 private:
  uint32_t Read(size_t at, int n, bool big_endian) const {
    uint32_t value = 0;
    for (int i = 0; i < n; ++i) value |= uint32_t(data_[at + size_t(i)]) << (8 * (big_endian ? n - 1 - i : i));
    return value;
  }
  const uint8_t* data_;
  size_t size_;
};

std::optional<cv::Size> Sized(int64_t width, int64_t height) {
  constexpr int64_t kMax = std::numeric_limits<int>::max();
  if (width <= 0 || height <= 0 || width > kMax || height > kMax) return std::nullopt;
  return cv::Size(int(width), int(height));
}

// BMP: the file header (14 bytes), then the DIB header: its size, then
// width and height (2 bytes each in the 12-byte OS/2 header, else 4,
// signed: a negative height is a top-down image).
std::optional<cv::Size> Bmp(const Bytes& b) {
  if (!b.Has(14, 4)) return std::nullopt;
  if (b.Le(14, 4) == 12) return b.Has(18, 4) ? Sized(b.Le(18, 2), b.Le(20, 2)) : std::nullopt;
  if (!b.Has(18, 8)) return std::nullopt;
  const int64_t width = int32_t(b.Le(18, 4)), height = int32_t(b.Le(22, 4));
  return Sized(width, height < 0 ? -height : height);
}

// PNM (P1-P6): the magic, then width and height in ASCII decimal,
// separated by whitespace and '#' comments to the end of the line.
std::optional<cv::Size> Pnm(const Bytes& b) {
  size_t at = 2;
  int64_t values[2];
  for (int64_t& value : values) {
    for (;;) {  // whitespace and comments
      if (!b.Has(at, 1)) return std::nullopt;
      if (b.At(at) == '#') {
        while (b.Has(at, 1) && b.At(at) != '\n') ++at;
      } else if (std::isspace(b.At(at))) {
        ++at;
      } else {
        break;
      }
    }
    value = 0;
    int digits = 0;
    for (; b.Has(at, 1) && std::isdigit(b.At(at)); ++at)
      if (++digits > 10) return std::nullopt;
      else value = value * 10 + (b.At(at) - '0');
    if (digits == 0) return std::nullopt;
  }
  return Sized(values[0], values[1]);
}

// TIFF (TIFF 6.0, section 2): the byte order, 42, the first IFD's offset;
// its entries (12 bytes: tag, type, count, value) give ImageWidth (256) and
// ImageLength (257), SHORT or LONG.
std::optional<cv::Size> Tiff(const Bytes& b) {
  const bool big = b.At(0) == 'M';
  auto read = [&](size_t at, int n) { return big ? b.Be(at, n) : b.Le(at, n); };
  if (!b.Has(0, 8) || read(2, 2) != 42) return std::nullopt;
  const size_t ifd = read(4, 4);
  if (!b.Has(ifd, 2)) return std::nullopt;
  const size_t entries = read(ifd, 2);
  int64_t width = 0, height = 0;
  for (size_t i = 0; i < entries; ++i) {
    const size_t at = ifd + 2 + 12 * i;
    if (!b.Has(at, 12)) return std::nullopt;
    const uint32_t tag = read(at, 2), type = read(at + 2, 2);
    if (tag != 256 && tag != 257) continue;
    if (type != 3 && type != 4) return std::nullopt;
    (tag == 256 ? width : height) = type == 3 ? read(at + 8, 2) : read(at + 8, 4);
  }
  return Sized(width, height);
}

}  // namespace

std::optional<cv::Size> ImageHeaderSize(const uint8_t* data, size_t size) {
  if (const auto compressed = CompressedImageSize(data, size)) return Sized(compressed->width, compressed->height);
  const Bytes b(data, size);
  if (b.Starts("BM")) return Bmp(b);
  if (b.Has(0, 2) && b.At(0) == 'P' && b.At(1) >= '1' && b.At(1) <= '6') return Pnm(b);
  if (b.Starts("II*") || b.Starts("MM")) return Tiff(b);
  return std::nullopt;
}

std::optional<cv::Size> ImageHeaderSize(const std::string& path, std::string* why) {
  struct stat info;
  if (stat(path.c_str(), &info) != 0) {
    *why = std::strerror(errno);  // a symlink loop: "Too many levels of symbolic links"
    return std::nullopt;
  }
  if (!S_ISREG(info.st_mode)) {
    *why = "not a regular file";
    return std::nullopt;
  }
  const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) {
    *why = std::strerror(errno);
    return std::nullopt;
  }
  std::vector<uint8_t> head(std::min<size_t>(kImageHeaderBytes, size_t(info.st_size)));
  size_t got = 0;
  while (got < head.size()) {
    const ssize_t n = read(fd, head.data() + got, head.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    got += size_t(n);
  }
  close(fd);
  const auto size = ImageHeaderSize(head.data(), got);
  if (!size) *why = "no PNG, JPEG, BMP, PNM or TIFF header with a size in its first " +
                    std::to_string(std::min(got, kImageHeaderBytes) / 1024) + " KB";
  return size;
}

std::optional<cv::Size> DecodableImageSize(const std::string& path, int64_t max_pixels, std::string* why) {
  const auto size = ImageHeaderSize(path, why);
  if (!size || int64_t(size->width) * size->height <= max_pixels) return size;
  *why = std::to_string(size->width) + "x" + std::to_string(size->height) + " pixels, more than the " +
         std::to_string(max_pixels) + " an image may have";
  return std::nullopt;
}

}  // namespace ws
