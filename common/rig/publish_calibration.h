// The one way a process puts a calibration on the bus (STEREO_CALIBRATION):
// stereo-calibrate after a solve, stereo-health after a refinement.
#pragma once

#include "runtime/process.h"
#include "widestereo/stereo_calibration_t.hpp"

namespace ws {

void PublishCalibration(Process& process, const widestereo::stereo_calibration_t& msg);

}  // namespace ws
