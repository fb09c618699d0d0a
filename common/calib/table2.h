// The paper's Table II: the final reprojection RMS of each distortion model
// for each camera (and, here, the stereo solve), as text.
//
//   Table II: final RMS of minimisation [px]
//   model        left      right     stereo
//   bspline      0.0998    0.1002    0.1001
//   poly6        1.2345    ...
#pragma once

#include <string>
#include <vector>

#include "calib/calibrate.h"

namespace ws::calib {

struct TableRow {
  std::string model;
  double left_rms = -1, right_rms = -1, stereo_rms = -1;  // negative: not available
};

std::vector<TableRow> TableRows(const std::vector<StereoCalibration>& calibrations);
std::string FormatTableII(const std::vector<TableRow>& rows,
                          const std::string& title = "Table II: final RMS of minimisation [px]");

}  // namespace ws::calib
