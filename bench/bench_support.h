// What the benchmarks share: timing and the simulator's true rig.
#pragma once

#include <algorithm>
#include <chrono>
#include <functional>
#include <vector>

#include "rectify/stereo_rig.h"
#include "sim/sim_config.h"

namespace ws::bench {

// The median (the upper one of an even count) of non-empty values.
inline double Median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

// The wall-clock milliseconds `fn` takes.
inline double Milliseconds(const std::function<void()>& fn) {
  const auto start = std::chrono::steady_clock::now();
  fn();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// The simulator config's true rig (cameras, R, T).
inline StereoRig TrueRig(const SimConfig& sim) {
  StereoRig rig;
  rig.left = sim.left;
  rig.right = sim.right;
  for (int i = 0; i < 9; ++i) rig.R(i / 3, i % 3) = sim.R.val[i];
  for (int i = 0; i < 3; ++i) rig.T(i) = sim.T[i];
  return rig;
}

}  // namespace ws::bench
