#include "rectify/calibration_size.h"

#include <stdexcept>

namespace ws {
namespace {

std::string SizeText(int64_t width, int64_t height) {
  return std::to_string(width) + "x" + std::to_string(height);
}

void RequireAtMost(cv::Size size, int64_t max_pixels, const std::string& what) {
  const int64_t pixels = int64_t(size.width) * size.height;
  if (pixels > max_pixels)
    throw std::invalid_argument(what + " " + SizeText(size.width, size.height) + " is " + std::to_string(pixels) +
                                " pixels, more than --max-image-pixels " + std::to_string(max_pixels));
}

}  // namespace

Rectification CalibrationGeometry(const Rig& rig, const RectifyOptions& options, int64_t max_pixels,
                                  const std::string& source) {
  const cv::Size size(rig.left.image_width, rig.left.image_height);
  if (size != cv::Size(rig.right.image_width, rig.right.image_height))
    throw std::invalid_argument(source + " refused: the two cameras have different image sizes, " +
                                SizeText(size.width, size.height) + " and " +
                                SizeText(rig.right.image_width, rig.right.image_height));
  RequireAtMost(size, max_pixels, source + " refused: its image size");
  // Two cameras at one place have no epipolar geometry (OpenCV's
  // stereoRectify would assert): no disparity, no depth.
  if (!(rig.T.norm() > 0))
    throw std::invalid_argument(source + " refused: a zero baseline (T = 0): the two cameras are at one place, "
                                         "no depth can be had from them");
  try {
    Rectification geometry = RectificationGeometry(rig, options);
    // The grid its maps sample: the rectified image at full resolution.
    RequireAtMost(geometry.size * geometry.downscale, max_pixels, "its rectified image size");
    return geometry;
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(source + " refused: " + e.what());
  }
}

void RequireFrameSize(const widestereo::stereo_frame_t& frame, cv::Size size, const std::string& source) {
  for (const widestereo::image_t* image : {&frame.left, &frame.right})
    if (image->width != size.width || image->height != size.height)
      throw std::invalid_argument("frame " + std::to_string(frame.frame_id) + " is " +
                                  SizeText(image->width, image->height) + " but " + source + " is for " +
                                  SizeText(size.width, size.height));
}

}  // namespace ws
