// The simulator's true rig as stereo-match takes it and as a calibration
// file (calib/calib_file.h): what a perfect calibration would give, for
// tests, benchmarks and comparisons.
#pragma once

#include "calib/calib_file.h"
#include "rectify/stereo_rig.h"
#include "sim/ground_truth.h"
#include "sim/sim_config.h"

namespace ws {

// The cameras, R and T of a simulator config (SimConfig) or of the truth
// file it wrote (SimTruth): both name them left, right, R, T.
template <class Sim>
StereoRig TrueStereoRig(const Sim& sim) {
  StereoRig rig;
  rig.left = sim.left;
  rig.right = sim.right;
  for (int i = 0; i < 9; ++i) rig.R(i / 3, i % 3) = sim.R.val[i];
  for (int i = 0; i < 3; ++i) rig.T(i) = sim.T[i];
  return rig;
}

calib::CalibrationFile TrueCalibration(const SimTruth& truth);

}  // namespace ws
