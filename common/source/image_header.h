// An image file's pixel size from its header, read before anything is
// decoded: what a file claims bounds what decoding it would cost, at the
// cost of its first kilobytes (a 2 KB JPEG may claim 32000 x 32000 pixels,
// which cv::imread would then allocate). The formats of image_folder.h:
// PNG and JPEG (lcm_io/compressed_size.h: IHDR, the first SOFn frame
// header), BMP (the DIB header), PNM (P1-P6) and TIFF (the first IFD's
// ImageWidth and ImageLength).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include <opencv2/core.hpp>

namespace ws {

// The size the header in `data` (a file's first `size` bytes) gives; none
// when it is no header of these formats, is damaged, claims a size of 0 or
// more than 2^31 - 1 a side, or lies beyond `size`. Reads no byte past
// data + size.
std::optional<cv::Size> ImageHeaderSize(const uint8_t* data, size_t size);

// The same for the file `path`, of which at most kImageHeaderBytes are read;
// none, with `*why` saying why, when it is not a regular file (a folder, a
// device, a FIFO, a symlink loop) or cannot be read or sized.
inline constexpr size_t kImageHeaderBytes = size_t(256) << 10;
std::optional<cv::Size> ImageHeaderSize(const std::string& path, std::string* why);

// ImageHeaderSize(path), and none, with `*why` saying so, also for more
// than `max_pixels`: the size of an image that may be decoded.
std::optional<cv::Size> DecodableImageSize(const std::string& path, int64_t max_pixels, std::string* why);

}  // namespace ws
