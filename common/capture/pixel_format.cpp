#include "capture/pixel_format.h"

#include <cstdio>
#include <cstring>

#include <arv.h>
#include <opencv2/imgproc.hpp>

#include "capture/camera_error.h"

namespace ws {
namespace {

struct FormatInfo {
  const char* name;
  uint32_t code;
  int mat_type;      // of the image as the camera sends it
  int color_to_bgr;  // cv::cvtColor code to BGR, -1 when none is needed
};

const FormatInfo kFormats[] = {
    {"Mono8", ARV_PIXEL_FORMAT_MONO_8, CV_8UC1, -1},
    {"Mono16", ARV_PIXEL_FORMAT_MONO_16, CV_16UC1, -1},
    {"RGB8", ARV_PIXEL_FORMAT_RGB_8_PACKED, CV_8UC3, cv::COLOR_RGB2BGR},
    {"BGR8", ARV_PIXEL_FORMAT_BGR_8_PACKED, CV_8UC3, -1},
};

std::string SupportedList() {
  std::string list;
  for (const FormatInfo& format : kFormats)
    list += std::string(list.empty() ? "" : ", ") + format.name;
  return list;
}

const FormatInfo& Find(uint32_t code) {
  for (const FormatInfo& format : kFormats)
    if (format.code == code) return format;
  throw CameraError("pixel format " + PixelFormatName(code) +
                    " is not supported (supported: " + SupportedList() + ")");
}

// `image` with `channels` channels (1 or 3, colour in BGR order).
cv::Mat WithChannels(const cv::Mat& image, int channels) {
  if (image.channels() == channels) return image;
  cv::Mat out;
  if (channels == 1)
    cv::cvtColor(image, out, image.channels() == 4 ? cv::COLOR_BGRA2GRAY : cv::COLOR_BGR2GRAY);
  else
    cv::cvtColor(image, out, image.channels() == 4 ? cv::COLOR_BGRA2BGR : cv::COLOR_GRAY2BGR);
  return out;
}

cv::Mat WithDepth(const cv::Mat& image, int depth) {
  if (image.depth() == depth) return image;
  cv::Mat out;
  image.convertTo(out, depth, depth == CV_16U ? 257.0 : 1.0 / 257.0);
  return out;
}

}  // namespace

const std::vector<std::string>& SupportedPixelFormats() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> list;
    for (const FormatInfo& format : kFormats) list.emplace_back(format.name);
    return list;
  }();
  return names;
}

uint32_t PixelFormatCode(const std::string& name) {
  for (const FormatInfo& format : kFormats)
    if (name == format.name) return format.code;
  throw CameraError("pixel format '" + name + "' is not supported (supported: " + SupportedList() +
                    ")");
}

std::string PixelFormatName(uint32_t code) {
  for (const FormatInfo& format : kFormats)
    if (format.code == code) return format.name;
  char hex[16];
  std::snprintf(hex, sizeof hex, "0x%08x", unsigned(code));
  return hex;
}

size_t BytesPerPixel(uint32_t code) { return CV_ELEM_SIZE(Find(code).mat_type); }

cv::Mat PixelsToMat(const void* data, size_t size, int width, int height, size_t row_stride,
                    uint32_t code) {
  const FormatInfo& format = Find(code);
  const size_t row_bytes = size_t(width) * CV_ELEM_SIZE(format.mat_type);
  if (width <= 0 || height <= 0 || row_stride < row_bytes)
    throw CameraError(
        cv::format("bad image layout: %dx%d, row stride %zu", width, height, row_stride));
  const size_t needed = row_stride * size_t(height - 1) + row_bytes;
  if (size < needed)
    throw CameraError(cv::format("image data too short: %zu bytes for %dx%d %s", size, width,
                                 height, format.name));
  const cv::Mat view(height, width, format.mat_type, const_cast<void*>(data), row_stride);
  cv::Mat image;
  if (format.color_to_bgr >= 0)
    cv::cvtColor(view, image, format.color_to_bgr);
  else
    view.copyTo(image);
  return image;
}

void MatToPixels(const cv::Mat& image, uint32_t code, int width, int height, void* data) {
  const FormatInfo& format = Find(code);
  cv::Mat out(height, width, format.mat_type, data);
  if (image.empty()) {
    out.setTo(0);
    return;
  }
  if ((image.depth() != CV_8U && image.depth() != CV_16U) ||
      (image.channels() != 1 && image.channels() != 3 && image.channels() != 4))
    throw CameraError(
        cv::format("cannot serve an image of OpenCV type %d (need 8 or 16 bits, "
                   "1, 3 or 4 channels)",
                   image.type()));
  cv::Mat converted =
      WithDepth(WithChannels(image, CV_MAT_CN(format.mat_type)), CV_MAT_DEPTH(format.mat_type));
  if (converted.size() != out.size()) {
    cv::Mat resized;
    cv::resize(converted, resized, out.size(), 0, 0, cv::INTER_AREA);
    converted = resized;
  }
  if (format.code == ARV_PIXEL_FORMAT_RGB_8_PACKED)
    cv::cvtColor(converted, out, cv::COLOR_BGR2RGB);
  else
    converted.copyTo(out);
}

}  // namespace ws
