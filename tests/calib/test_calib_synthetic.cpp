// Calibration of synthetic rigs: the mustache lens (the project's Theia-like
// table) and an ordinary poly6 barrel lens, 0.1 px corner noise.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "calib/calibrate.h"
#include "calib/synthetic_rig.h"

namespace {

using namespace ws;
using namespace ws::calib;

SyntheticRigOptions MustacheRig() {
  SyntheticRigOptions o;
  o.left = MustacheTestCamera(0);
  o.right = MustacheTestCamera(1);
  o.R = Pose{{0.004, -0.012, 0.003, 0, 0, 0}}.R();
  o.T = {-0.12, 0.0015, 0.002};
  return o;
}

TEST(CalibSynthetic, Explore) {
  const SyntheticRig rig = MakeSyntheticRig(MustacheRig());
  int left = 0, right = 0, both = 0;
  for (int v = 0; v < rig.data.size(); ++v) {
    left += !rig.data.left.views[v].empty();
    right += !rig.data.right.views[v].empty();
    both += !rig.data.left.views[v].empty() && !rig.data.right.views[v].empty();
  }
  std::printf("views left %d right %d both %d\n", left, right, both);
  const double truth_rms = Rms(Reproject(MustacheTestCamera(0), rig.data.left, rig.left_poses));
  std::printf("truth rms left %.4f\n", truth_rms);
  for (const std::string kind : {"bspline", "poly6", "poly12"}) {
    CalibrationOptions options;
    options.model = kind;
    const StereoCalibration r = CalibrateStereo(rig.data, options);
    std::printf("%s: left %.4f right %.4f stereo %.4f  %.2fs  fx %.3f (%.3f) cx %.3f (%.3f) T %.5f %.5f %.5f init %s rmax obs %.3f\n",
                kind.c_str(), r.left.rms_px, r.right.rms_px, r.rms_px, r.solve_seconds,
                r.left.model.fx, r.left.stddev.empty() ? -1 : r.left.stddev[0], r.left.model.cx,
                r.left.stddev.empty() ? -1 : r.left.stddev[2], r.T.x(), r.T.y(), r.T.z(),
                r.left.init_method.c_str(), r.left.max_observed_radius);
  }
}

}  // namespace
