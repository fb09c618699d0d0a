// Conversions between widestereo::image_t messages and cv::Mat.
#pragma once

#include <stdexcept>
#include <string>

#include <opencv2/core.hpp>

#include "widestereo/image_t.hpp"

namespace ws {

// A message whose fields disagree with its payload, or that cannot be decoded.
struct DecodeError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

enum class Compression { none, jpeg, png };

// Parses "none", "jpeg" or "png"; throws std::invalid_argument otherwise.
Compression ParseCompression(const std::string& name);

// Whether an image (or a camera) of this size is one we accept anywhere: at
// most 65536 pixels a side and 2^28 pixels in all.
bool ImageSizeAcceptable(int64_t width, int64_t height);

// Whether the message is no image at all (width = height = size = 0): the
// missing camera of a one-camera rig (stereo_frame_t).
bool IsNoImage(const widestereo::image_t& msg);
// The no-image message.
widestereo::image_t NoImage(int64_t utime);

// Checks that width, height, row_stride, size and the payload agree for the
// message's pixel format, before any pixel is touched. Throws DecodeError.
void ValidateImage(const widestereo::image_t& msg);

// Decodes an image message into a cv::Mat: CV_8UC1 (GRAY), CV_16UC1
// (LE_GRAY16), CV_8UC3 in BGR order (RGB, BGR), CV_32FC1 (FLOAT_GRAY32);
// JPEG (MJPEG) and PNG payloads are decoded and must match width and height.
// The result owns its pixels. Throws DecodeError.
cv::Mat ImageToMat(const widestereo::image_t& msg);
// The same without a copy where the payload already is the cv::Mat's pixels
// (every raw format but RGB): the result then points into msg.data, valid
// while msg lives unchanged. Throws DecodeError.
cv::Mat ImageView(const widestereo::image_t& msg);

// Encodes a CV_8UC1, CV_16UC1, CV_8UC3 (BGR) or CV_32FC1 Mat; with jpeg or
// png compression the payload is that file (JPEG: 8-bit only).
widestereo::image_t MatToImage(const cv::Mat& mat, int64_t utime,
                               Compression compression = Compression::none,
                               int jpeg_quality = 95);

}  // namespace ws
