// ROS camera_info YAML, the format camera_calibration_parsers reads and
// camera_info_manager loads (sensor_msgs/CameraInfo's fields):
//
//   image_width: 800
//   image_height: 503
//   camera_name: left
//   camera_matrix: {rows: 3, cols: 3, data: [...]}          K
//   distortion_model: plumb_bob                              or equidistant, rational_polynomial
//   distortion_coefficients: {rows: 1, cols: N, data: [...]} D
//   rectification_matrix: {rows: 3, cols: 3, data: [...]}   R: camera -> rectified
//   projection_matrix: {rows: 3, cols: 4, data: [...]}      P: rectified camera
#pragma once

#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "models/camera_model.h"

namespace ws {

struct RosCameraInfo {
  std::string name;
  int width = 0, height = 0;
  cv::Matx33d K;
  std::string distortion_model;
  std::vector<double> D;
  cv::Matx33d R;
  cv::Matx34d P;
};

// Every number at full precision, each line of `comments` first as a #
// line. Throws std::runtime_error when it cannot write.
void WriteRosCameraInfo(const std::string& path, const RosCameraInfo& info,
                        const std::vector<std::string>& comments);

// Reads a camera_info file (what WriteRosCameraInfo and ROS's
// camera_calibration write), every field checked. Throws
// CalibrationFileError "FILE: FIELD: REASON".
RosCameraInfo ReadRosCameraInfo(const std::string& path);

// The camera `info` describes as widestereo's model: plumb_bob (k1 k2 p1 p2
// k3, or no coefficients) as poly6, rational_polynomial with OpenCV's 14
// (CALIB_TILTED_MODEL: image_geometry hands D to OpenCV as it stands) and
// only k1 k2 p1 p2 k3 and the tilt set as poly6 with its sensor tilt,
// equidistant (k1 k2 k3 k4) as kb4.
// Throws CalibrationFileError naming `path` for another distortion model.
CameraModel RosCameraModel(const RosCameraInfo& info, const std::string& path);

}  // namespace ws
