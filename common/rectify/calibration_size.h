// The image size a calibration is for, and the frames it may be used on,
// checked on the numbers alone: before any rectification map is built or any
// pixel decoded, so that neither a calibration of an absurd size nor a frame
// of another size costs memory or time. stereo-match builds a calibration's
// maps once it passes these checks, stereo-health for its first frame.
#pragma once

#include <cstdint>
#include <string>

#include <opencv2/core.hpp>

#include "rectify/rectification.h"
#include "widestereo/stereo_frame_t.hpp"

namespace ws {

// The rig's rectification without its maps (RectificationGeometry), its
// input_size the image size both cameras are calibrated for. Throws
// std::invalid_argument, naming `source`, when the two sizes differ, when
// that size or the rectified image's is more than max_pixels
// (--max-image-pixels), or when the rig cannot be rectified.
Rectification CalibrationGeometry(const Rig& rig, const RectifyOptions& options, int64_t max_pixels,
                                  const std::string& source);

// Throws std::invalid_argument "frame N is WxH but <source> is for WxH" when
// either image of the frame, by its width and height fields, is not `size`.
// (ValidateImage holds a compressed payload to those fields.)
void RequireFrameSize(const widestereo::stereo_frame_t& frame, cv::Size size, const std::string& source);

}  // namespace ws
