// The simulator's true rig as a calibration file (calib/calib_file.h): what a
// perfect calibration would write, for benchmarks and comparisons.
#pragma once

#include "calib/calib_file.h"
#include "sim/ground_truth.h"

namespace ws {

calib::CalibrationFile TrueCalibration(const SimTruth& truth);

}  // namespace ws
