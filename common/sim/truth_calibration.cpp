#include "sim/truth_calibration.h"

namespace ws {

calib::CalibrationFile TrueCalibration(const SimTruth& truth) {
  const StereoRig rig = TrueStereoRig(truth);
  calib::CalibrationFile file;
  file.model = rig.left.distortion.kind;
  file.left = rig.left;
  file.right = rig.right;
  file.R = rig.R;
  file.T = rig.T;
  return file;
}

}  // namespace ws
