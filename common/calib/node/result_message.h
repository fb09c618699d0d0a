// A solve's outcome for viewers (channel CALIBRATION_RESULT, stereo-view):
// the model table (fitted and held-out RMS of every model asked for, the
// failures with their reason), the chosen model, and its residual and
// projection-uncertainty maps per camera.
#pragma once

#include <cstdint>

#include "calib/calibrate.h"
#include "widestereo/calibration_result_t.hpp"

namespace ws::calib {

widestereo::calibration_result_t ToResultMessage(const ModelCalibrations& results, int64_t utime);

// One camera's residual and projection-uncertainty maps.
widestereo::camera_maps_t ToMapsMessage(const CameraCalibration& camera);

}  // namespace ws::calib
