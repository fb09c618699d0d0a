// The GenICam pixel formats widestereo reads from cameras and serves from fake
// ones (names and codes as in the GenICam PFNC), and their conversions to and
// from cv::Mat.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace ws {

// "Mono8", "Mono16", "RGB8", "BGR8".
const std::vector<std::string>& SupportedPixelFormats();

// The PFNC code of a supported format name; throws CameraError for others.
uint32_t PixelFormatCode(const std::string& name);

// The name of a supported code, or the code in hex ("0x01080008").
std::string PixelFormatName(uint32_t code);

// Bytes per pixel of a supported code; throws CameraError for others.
size_t BytesPerPixel(uint32_t code);

// Copies a camera image into a Mat that owns its pixels: Mono8 -> CV_8UC1,
// Mono16 -> CV_16UC1, RGB8 and BGR8 -> CV_8UC3 in BGR order. Rows are
// row_stride bytes apart. Throws CameraError when `size` is too small for the
// image or the format is not supported.
cv::Mat PixelsToMat(const void* data, size_t size, int width, int height, size_t row_stride,
                    uint32_t code);

// Writes `image` as a width x height image of format `code` into `data`
// (width * height * BytesPerPixel(code) bytes), converting as needed: gray to
// colour and back, 8 to 16 bits (x 257) and back, and any size (resized). An
// empty image is written black. Accepts CV_8U or CV_16U with 1, 3 or 4
// channels (colour in BGR order); throws CameraError for anything else.
void MatToPixels(const cv::Mat& image, uint32_t code, int width, int height, void* data);

}  // namespace ws
