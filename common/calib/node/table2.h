// The paper's Table II: the final reprojection RMS of each distortion model
// for each camera (and, here, the stereo solve), as text; beside it each
// camera's cross-validated (held-out, heldout.h) RMS and estimated
// coefficient count, and a '*' on the model published (calibrate.h,
// ModelCalibrations::chosen).
//
//   Table II: final RMS of minimisation [px]
//   model        left      right     stereo   left CV  right CV   coeffs
//   bspline *    0.0998    0.1002    0.1001    0.1040    0.1046    16/16
//   poly6        1.2345    ...
#pragma once

#include <string>
#include <vector>

#include "calib/calibrate.h"

namespace ws::calib {

struct TableRow {
  std::string model;
  double left_rms = -1, right_rms = -1, stereo_rms = -1;  // negative: not available
  double left_heldout = -1, right_heldout = -1;
  std::string coeffs;  // estimated distortion coefficients, left/right
  bool chosen = false;
};

// One row per calibration; `chosen` (an index, -1: none) marked.
std::vector<TableRow> TableRows(const std::vector<StereoCalibration>& calibrations, int chosen = -1);
std::string FormatTableII(const std::vector<TableRow>& rows,
                          const std::string& title = "Table II: final RMS of minimisation [px]");

}  // namespace ws::calib
