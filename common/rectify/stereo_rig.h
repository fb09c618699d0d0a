// A calibrated stereo rig: two cameras and the pose of the right camera
// relative to the left, X_right = R X_left + T (OpenCV's convention).
#pragma once

#include <cstdint>
#include <string>

#include <Eigen/Core>

#include "models/camera_model.h"
#include "widestereo/stereo_calibration_t.hpp"

namespace ws {

struct StereoRig {
  CameraModel left;
  CameraModel right;
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d T = Eigen::Vector3d::Zero();  // metres
};

// The camera model a calibration message carries. Throws std::invalid_argument
// when the message does not describe a usable camera.
CameraModel CameraModelFromMessage(const widestereo::camera_calibration_t& msg);
StereoRig StereoRigFromMessage(const widestereo::stereo_calibration_t& msg);
// The rig of a calibration file (calib/calib_file.h, stereo-calibrate --out).
// Throws calib::CalibrationFileError naming the file, the field and the reason.
StereoRig StereoRigFromFile(const std::string& path);

// The other way: the message of a camera model named `name` ("left",
// "right") and of a rig, with no quality figures (rms 0, no views, no
// parameter deviations), e.g. for a simulator's true cameras.
widestereo::camera_calibration_t MessageFromCameraModel(const CameraModel& model,
                                                        const std::string& name);
widestereo::stereo_calibration_t MessageFromStereoRig(const StereoRig& rig, int64_t utime);

}  // namespace ws
