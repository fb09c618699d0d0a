// A solve's result (StereoCalibration, calibrate.h) as the rig record
// (rig/rig.h), for the calibration file, and as the STEREO_CALIBRATION
// message: the rig's message (rig/rig_message.h) with the solve's detail,
// per-view RMS over the input views (-1 for views that were not used), the
// parameter names and their standard deviations.
#pragma once

#include <cstdint>

#include "calib/calibrate.h"
#include "rig/rig.h"
#include "widestereo/stereo_calibration_t.hpp"

namespace ws::calib {

Rig ToRig(const StereoCalibration& calibration);

widestereo::camera_calibration_t ToMessage(const CameraCalibration& camera);
widestereo::stereo_calibration_t ToMessage(const StereoCalibration& calibration, int64_t utime);

}  // namespace ws::calib
