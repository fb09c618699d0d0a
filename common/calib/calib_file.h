// The calibration file: YAML that OpenCV's cv::FileStorage reads directly.
//
//   cv::FileStorage fs("calib.yaml", cv::FileStorage::READ);
//   cv::Mat K, R, T;
//   fs["left"]["camera_matrix"] >> K;
//   fs["stereo"]["R"] >> R;  fs["stereo"]["T"] >> T;
//
// Layout (docs/calibration.md gives the model's exact definition):
//
//   model: bspline                     the kind of both cameras' models
//   left:                              and right: the same keys
//     image_width: 1280
//     image_height: 960
//     camera_matrix: !!opencv-matrix   3x3, [fx 0 cx; 0 fy cy; 0 0 1]
//     model: bspline                   bspline | poly6 | poly12
//     degree: 3                        B-spline degree (0 for poly)
//     knots: [ ... ]                   the full clamped knot vector (bspline only)
//     alpha: [ ... ]                   every coefficient, alpha_0 = alpha_1 = 0 included (bspline)
//     k: [ ... ]                       k1..k3 or k1..k6 (poly6, poly12) instead of alpha
//     p1: ...
//     p2: ...
//     rms: ...                         reprojection RMS, pixels
//     views: ...
//   stereo:
//     R: !!opencv-matrix               3x3, X_right = R X_left + T
//     T: !!opencv-matrix               3x1, metres
//     rms: ...
//     baseline_m: ...
//     views: ...
#pragma once

#include <string>

#include <Eigen/Core>

#include "calib/calibrate.h"
#include "models/camera_model.h"

namespace ws::calib {

struct CalibrationFile {
  std::string model;
  CameraModel left, right;
  double left_rms = 0, right_rms = 0;
  int left_views = 0, right_views = 0;
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d T = Eigen::Vector3d::Zero();
  double rms = 0;
  int views = 0;
};

CalibrationFile ToCalibrationFile(const StereoCalibration& calibration);

// Writes the file (to a temporary beside it, then renamed, so a reader never
// sees half a file). Throws std::runtime_error when it cannot.
void WriteCalibrationFile(const std::string& path, const CalibrationFile& file);

// Reads and checks a calibration file (the models must be consistent, e.g.
// alpha's length must match the knots). Throws std::runtime_error naming the
// file and the problem.
CalibrationFile ReadCalibrationFile(const std::string& path);

}  // namespace ws::calib
