// Conversions between widestereo::image_t messages and cv::Mat.
#pragma once

#include <stdexcept>
#include <string>

#include <opencv2/core.hpp>

#include "models/image_size.h"  // ImageSizeAcceptable
#include "widestereo/image_t.hpp"

namespace ws {

// A message whose fields disagree with its payload, or that cannot be decoded.
struct DecodeError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

enum class Compression { none, jpeg, png };

// Parses "none", "jpeg" or "png"; throws std::invalid_argument otherwise.
Compression ParseCompression(const std::string& name);

// The largest image a process decodes or builds rectification maps for,
// unless its --max-image-pixels says otherwise: 2^25 pixels (33.5 M), above
// the largest GigE Vision sensors (5472x3648, 20.0 M; 5328x4608, 24.6 M) and
// 27 times the rig's 1280x960. A decoded BGR image of it is 100 MB
// (docs/reliability.md, "Bounded inputs").
inline constexpr int64_t kDefaultMaxImagePixels = int64_t(1) << 25;

// Throws DecodeError when a width x height image is more than max_pixels:
// "a 16384x16384 image is 268435456 pixels, more than --max-image-pixels 33554432".
void RequireAtMostPixels(int64_t width, int64_t height, int64_t max_pixels);

// Whether the message is no image at all (width = height = size = 0): the
// missing camera of a one-camera rig (stereo_frame_t).
bool IsNoImage(const widestereo::image_t& msg);
// The no-image message.
widestereo::image_t NoImage(int64_t utime);

// Checks that width, height, row_stride, size and the payload agree for the
// message's pixel format, before any pixel is touched: a JPEG or PNG payload
// must say the message's width and height in its own header (SOFn, IHDR;
// lcm_io/compressed_size.h). Throws DecodeError.
void ValidateImage(const widestereo::image_t& msg);

// Decodes an image message into a cv::Mat: CV_8UC1 (GRAY), CV_16UC1
// (LE_GRAY16), CV_8UC3 in BGR order (RGB, BGR), CV_32FC1 (FLOAT_GRAY32).
// The message is validated first (ValidateImage), and an image of more than
// max_pixels is refused before it is decoded. The result owns its pixels.
// Throws DecodeError.
cv::Mat ImageToMat(const widestereo::image_t& msg, int64_t max_pixels = kDefaultMaxImagePixels);
// As ImageToMat, but a raw GRAY, LE_GRAY16, BGR or FLOAT_GRAY32 image is not
// copied: the result shares the message's pixels, and is valid while the
// message lives unchanged (for a reader that is done with the pixels before
// the message goes: a remap, an encoder). Other formats are decoded.
cv::Mat ImageView(const widestereo::image_t& msg, int64_t max_pixels = kDefaultMaxImagePixels);

// Encodes a CV_8UC1, CV_16UC1, CV_8UC3 (BGR) or CV_32FC1 Mat; with jpeg or
// png compression the payload is that file (JPEG: 8-bit only).
widestereo::image_t MatToImage(const cv::Mat& mat, int64_t utime,
                               Compression compression = Compression::none,
                               int jpeg_quality = 95);

}  // namespace ws
