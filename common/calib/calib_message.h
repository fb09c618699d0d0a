// A calibration as the STEREO_CALIBRATION message (stereo_calibration_t) and
// back. camera_calibration_t carries the full coefficient vector (for a
// B-spline alpha_0 = alpha_1 = 0 included), the parameter names and their
// standard deviations; per-view RMS is over the input views, -1 for views
// that were not used. (rectify/stereo_rig.h reads a message back.)
#pragma once

#include <cstdint>

#include "calib/calib_file.h"
#include "calib/calibrate.h"
#include "models/camera_model.h"
#include "widestereo/stereo_calibration_t.hpp"

namespace ws::calib {

widestereo::camera_calibration_t ToMessage(const CameraCalibration& camera);
widestereo::stereo_calibration_t ToMessage(const StereoCalibration& calibration, int64_t utime);
// A calibration file as the message (RMS and view counts kept; no per-view
// RMS or deviations) and a message as the file (its quality figures kept).
widestereo::stereo_calibration_t ToMessage(const CalibrationFile& file, int64_t utime);
CalibrationFile ToCalibrationFile(const widestereo::stereo_calibration_t& msg);

}  // namespace ws::calib
