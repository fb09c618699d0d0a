// Whether another tool's format holds a widestereo camera exactly, and as
// which of its models: the one place stereo-export decides exact or not.
//
//   widestereo   OpenCV               ROS camera_info   Kalibr                mrcal
//   poly6        pinhole (5 coeffs)   plumb_bob         radtan if k3 = 0      LENSMODEL_OPENCV5
//   kb4          fisheye              equidistant       equidistant           -
//   poly12       as poly6 when k4 = k5 = k6 = 0, else -
//   poly6 + tilt pinhole (14 coeffs)  rational_polynomial (14)  -        -
//   bspline, bspline_theta: -
//
// and never with a non-radial field (models/nonradial_field.h) beyond the
// tilt.
// (OpenCV's, ROS's and mrcal's 8-coefficient model is rational, not poly12;
// mrcal 2.2 has no Kannala-Brandt model.) Everything else is exported
// another way, and says so: the rectification maps (OpenCV, ROS) or a
// fitted model with its error printed (Kalibr, mrcal).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "models/camera_model.h"

namespace ws {

enum class ExportFormat { kOpenCv, kRos, kKalibr, kMrcal };

// "opencv-stereo", "ros", "kalibr", "mrcal"; and back (throws
// std::invalid_argument naming the formats for any other name).
const char* ExportFormatName(ExportFormat format);
ExportFormat ParseExportFormat(const std::string& name);

// A camera as one of the target's own models: the model's name there and
// the distortion coefficients in the target's order (p1, p2 among them
// where it has them; the intrinsics fx, fy, cx, cy are the camera's own).
struct TargetModel {
  std::string name;
  std::vector<double> coeffs;
};

// The camera as a model of the format with the same projection, or nullopt
// when the format has none.
std::optional<TargetModel> ExactTargetModel(const CameraModel& camera, ExportFormat format);

}  // namespace ws
