// The simulator's true rig (rig/rig.h): what a perfect calibration would
// give, for tests, benchmarks and comparisons (no quality figures).
#pragma once

#include "rig/rig.h"
#include "sim/ground_truth.h"
#include "sim/sim_config.h"

namespace ws {

// The cameras, R and T of a simulator config (SimConfig) or of the truth
// file it wrote (SimTruth): both name them left, right, R, T.
template <class Sim>
Rig TrueStereoRig(const Sim& sim) {
  Rig rig;
  rig.left = sim.left;
  rig.right = sim.right;
  for (int i = 0; i < 9; ++i) rig.R(i / 3, i % 3) = sim.R.val[i];
  for (int i = 0; i < 3; ++i) rig.T(i) = sim.T[i];
  return rig;
}

}  // namespace ws
