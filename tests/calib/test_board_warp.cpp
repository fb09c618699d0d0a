// A board that is not flat (board_warp.h): the synthetic barrel rig's board
// bowed by 2 mm at its centre, calibrated with and without --board-warp, and
// a flat board with it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "calib_test_rigs.h"

namespace {

using namespace ws::calib;
using namespace ws::calib::test;

constexpr double kX2 = 1.2e-3, kY2 = 0.8e-3;  // metres: 2 mm at the centre

struct Solved {
  StereoCalibration result;
  double noise_rms;  // the corner noise's RMS distance: the floor a right model reaches
};

Solved Calibrate(const std::array<double, 2>& bow, bool estimate) {
  SyntheticRigOptions truth = BarrelRig();
  truth.board_warp = bow;
  const SyntheticRig rig = MakeSyntheticRig(truth);
  CalibrationOptions options;
  options.model = ws::ModelKind::kPoly6;
  options.board_warp = estimate ? WarpRule::kEstimated : WarpRule::kFlat;
  return {CalibrateStereo(rig.data, options), truth.noise_px * std::sqrt(2.0)};
}

void Print(const char* what, const Solved& s) {
  for (const CameraCalibration* c : {&s.result.left, &s.result.right}) {
    const BoardWarp& w = c->board_warp;
    std::printf("%s, %s: rms %.4f px (noise %.4f), bow x2 %.3f y2 %.3f centre %.3f mm", what,
                c->name.c_str(), c->rms_px, s.noise_rms,
                1e3 * w.data[0], 1e3 * w.data[1], 1e3 * w.Centre());
    if (c->board_warp_stddev.size() == 2)
      std::printf(" (sigma %.3f, %.3f mm)", 1e3 * c->board_warp_stddev[0],
                  1e3 * c->board_warp_stddev[1]);
    std::printf("\n");
  }
}

TEST(BoardWarp, RecoversATwoMillimetreBowAndItsResidualPattern) {
  const Solved flat_fit = Calibrate({kX2, kY2}, false);
  const Solved warp_fit = Calibrate({kX2, kY2}, true);
  Print("bowed board, flat model", flat_fit);
  Print("bowed board, --board-warp", warp_fit);
  for (int c = 0; c < 2; ++c) {
    const CameraCalibration& flat = c ? flat_fit.result.right : flat_fit.result.left;
    const CameraCalibration& warped = c ? warp_fit.result.right : warp_fit.result.left;
    // The bow the flat model cannot follow shows in its residuals ...
    EXPECT_GT(flat.rms_px, 1.5 * flat_fit.noise_rms) << flat.name;
    // ... and is gone once the board's shape is estimated.
    EXPECT_LT(warped.rms_px, 1.05 * warp_fit.noise_rms) << warped.name;
    ASSERT_TRUE(warped.board_warp.free);
    EXPECT_NEAR(warped.board_warp.data[0], kX2, 0.2e-3) << warped.name;
    EXPECT_NEAR(warped.board_warp.data[1], kY2, 0.2e-3) << warped.name;
    EXPECT_NEAR(warped.board_warp.Centre(), kX2 + kY2, 0.2e-3) << warped.name;
  }
}

TEST(BoardWarp, AFlatBoardGivesNoBowWithinItsSigma) {
  const Solved fit = Calibrate({0, 0}, true);
  Print("flat board, --board-warp", fit);
  for (const CameraCalibration* c : {&fit.result.left, &fit.result.right}) {
    ASSERT_EQ(c->board_warp_stddev.size(), 2u) << c->name;
    for (int k = 0; k < 2; ++k) {
      EXPECT_GT(c->board_warp_stddev[k], 0) << c->name;
      EXPECT_LT(std::abs(c->board_warp.data[k]), 3 * c->board_warp_stddev[k]) << c->name;
    }
  }
}

}  // namespace
