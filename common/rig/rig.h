// The calibrated rig: each camera's model (image size, intrinsics,
// distortion) with the quality of its fit, and the pose of the right camera
// relative to the left, X_right = R X_left + T (OpenCV's convention).
//
// The one record every process reads and writes:
//   rig/rig_file.h     the calibration file (stereo-calibrate --out), YAML
//   rig/rig_message.h  the STEREO_CALIBRATION message (stereo_calibration_t)
// A solve's result (calib::StereoCalibration) becomes one with calib::ToRig
// (calib/node/solved_rig.h); a camera alone is a CameraModel (models/).
#pragma once

#include <string>

#include <Eigen/Core>

#include "models/camera_model.h"

namespace ws {

struct Rig {
  CameraModel left, right;
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();  // X_right = R X_left + T
  Eigen::Vector3d T = Eigen::Vector3d::Zero();      // metres
  bool mono = false;  // one camera: `left` only, no right, R or T
  // The fit's quality (0 where unknown, e.g. a simulator's true rig).
  double left_rms = 0, right_rms = 0;  // reprojection RMS, pixels
  int left_views = 0, right_views = 0;  // views used
  double rms = 0;                       // stereo, pixels
  int views = 0;                        // stereo views used
  std::string note;  // written as a comment after the file's header (e.g. what refined it); not read back

  // The kind of both cameras' models (the file's top-level "model").
  ModelKind kind() const { return left.distortion.kind; }
};

}  // namespace ws
