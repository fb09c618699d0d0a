// Symmetric boards (half_turn.h): pairs whose images number the corners
// from opposite ends are renumbered, not fitted and not dropped.
#include <gtest/gtest.h>

#include <cstdio>

#include "calib_test_rigs.h"

namespace {

using namespace ws::calib;
using namespace ws::calib::test;

// The view numbered from the other end of the 12 x 9 board, as a detector
// may for a board that looks the same half-turned.
void HalfTurn(const SyntheticRigOptions& rig, BoardView* view) {
  const int n = rig.board_cols * rig.board_rows;
  for (int i = 0; i < view->size(); ++i) {
    view->ids[i] = n - 1 - view->ids[i];
    view->object[i] = {(rig.board_cols - 1) * rig.square - view->object[i].x(),
                       (rig.board_rows - 1) * rig.square - view->object[i].y(), 0};
  }
}

TEST(HalfTurn, RenumberedPairsGiveTheSameRig) {
  const SyntheticRigOptions truth = BarrelRig();
  const SyntheticRig rig = MakeSyntheticRig(truth);
  std::vector<int> pairs;  // views both cameras see
  for (int v = 0; v < rig.data.size(); ++v)
    if (!rig.data.left.views[v].empty() && !rig.data.right.views[v].empty()) pairs.push_back(v);
  ASSERT_GE(pairs.size(), 20u);
  const std::vector<int> half_turned = {pairs[3], pairs[7], pairs[12], pairs[19]};
  SyntheticRig turned = rig;
  for (int k = 0; k < 3; ++k) HalfTurn(truth, &turned.data.right.views[half_turned[k]]);
  HalfTurn(truth, &turned.data.left.views[half_turned[3]]);  // the other image of a pair
  CalibrationOptions options;
  options.model = ws::ModelKind::kPoly6;
  const StereoCalibration expected = CalibrateStereo(rig.data, options);
  const StereoCalibration result = CalibrateStereo(turned.data, options);
  std::printf("half-turned views renumbered: %zu, stereo views %d (as detected: %d), baseline "
              "%.6f m (%.6f m)\n",
              result.half_turned_views.size(), result.views, expected.views, result.T.norm(),
              expected.T.norm());
  EXPECT_TRUE(expected.half_turned_views.empty());
  EXPECT_EQ(result.half_turned_views, half_turned);
  EXPECT_TRUE(result.inconsistent_views.empty());
  EXPECT_EQ(result.views, expected.views);
  EXPECT_NEAR((result.T - expected.T).norm(), 0, 1e-6);
  EXPECT_NEAR((result.R - expected.R).norm(), 0, 1e-6);
  EXPECT_NEAR(result.right.rms_px, expected.right.rms_px, 1e-6);
  EXPECT_NEAR(result.left.rms_px, expected.left.rms_px, 1e-6);
}

}  // namespace
