#include "sim/truth_calibration.h"

namespace ws {

Rig TrueStereoRig(const SimConfig& sim) {
  Rig rig;
  rig.left = sim.left;
  rig.right = sim.right;
  for (int i = 0; i < 9; ++i) rig.R(i / 3, i % 3) = sim.R.val[i];
  for (int i = 0; i < 3; ++i) rig.T(i) = sim.T[i];
  return rig;
}

}  // namespace ws
