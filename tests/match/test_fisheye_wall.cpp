// An angle-model calibration downstream (issue #13): the simulator's
// 200-degree fisheye rig (config/sim/fisheye.yaml, its wall scene only)
// through stereo-match (a pinhole rectification of the central field) and
// stereo-cloud with the rig's bspline_theta calibration file: the wall 2.0 m
// in front comes back flat, at its distance, over the field both rectified
// images hold.
#include <gtest/gtest.h>

#include <cstdio>

#include "match_fixtures.h"
#include "rectify/rectification.h"
#include "test_support.h"
#include "wall_analysis.h"
#include "wall_chain.h"

namespace {

using namespace ws::test;


// Pinhole rectification of the central field at the cameras' resolution
// (focal scale 1: 130 x 116 degrees, its edges stretched about 5 times) and
// narrower (1.5: 110 x 94 degrees), and lat-lon (the default, `auto`, for
// this rig: the whole common field at the centre's angular resolution).
TEST(FisheyeWall, BsplineThetaCalibrationGivesTheWallAtTwoMetres) {
  const std::string dir = TempDir("fisheye-wall");
  const ws::SimTruth truth = CaptureWall(dir, FisheyeSceneConfig(dir, "wall"), 1);
  const ws::Rig rig = truth.rig;
  ASSERT_EQ(rig.left.distortion.kind, ws::ModelKind::kBsplineTheta);
  const double z = truth.frames.front().wall_distance;
  struct Mode {
    const char* name;
    ws::RectificationMode mode;
    double focal_scale, distance_tolerance, min_coverage;
  };
  // Lat-lon holds the whole wall both lenses see, out to where it is seen
  // edge-on: there its 2 cm dots are far below a pixel and its range
  // changes by metres for 0.1 px (the 90th percentile printed), so about
  // 0.7 of the pixels both see are matched, against 0.92 and 0.96 of the
  // pinholes' central parts. The box room (test_fisheye_room.cpp), which
  // shows texture all around, is where lat-lon's coverage is measured.
  const Mode modes[3] = {{"pinhole-f1.0", ws::RectificationMode::kPinhole, 1.0, 0.01, 0.85},
                         {"pinhole-f1.5", ws::RectificationMode::kPinhole, 1.5, 0.005, 0.85},
                         {"auto", ws::RectificationMode::kAuto, 1.0, 0.001, 0.6}};
  for (int m = 0; m < 3; ++m) {
    WallChainOptions options;
    options.focal_scale = modes[m].focal_scale;
    options.mode = modes[m].mode;
    const WallRun run = RunWallChain(dir, truth, rig, modes[m].name, 1, "64", options);
    ASSERT_EQ(run.wall.size(), 1u);
    const ws::Rectification rect = ws::BuildRectification(rig, {modes[m].focal_scale, {}, modes[m].mode});
    const WallFit& w = run.wall[0];
    const cv::Mat true_disparity =
        TrueWallDisparity(rect, rig, truth.frames.front().wall_normal, truth.frames.front().wall_offset);
    const int true_pixels = cv::countNonZero(true_disparity);
    const RangeAccuracy accuracy = PredictRangeAccuracy(rect, true_disparity);
    std::printf("[ wall ] fisheye, %s (%s, %d x %d, f %.1f): plane %.4f m (true %.1f m), RMS %.2f mm, "
                "disparity sigma %.3f px, density %.3f, coverage %.3f of the %d px both see\n",
                modes[m].name, ws::RectificationModeName(rect.mode), rect.size.width, rect.size.height,
                rect.f, w.offset, z, 1000 * w.inlier_rms, run.disparity[0].sigma,
                run.disparity[0].density, w.coverage, true_pixels);
    std::printf("[ wall ]   range change for a 0.1 px disparity error: %.1f mm at the centre, median %.1f mm, "
                "90th percentile %.1f mm over the wall both see\n",
                1000 * accuracy.centre, 1000 * accuracy.median, 1000 * accuracy.p90);
    EXPECT_NEAR(w.offset, z, modes[m].distance_tolerance * z) << modes[m].name;
    EXPECT_LT(w.tilt_rad, 0.01) << modes[m].name;
    EXPECT_GT(w.coverage, modes[m].min_coverage) << modes[m].name;
    EXPECT_GT(run.disparity[0].density, modes[m].min_coverage) << modes[m].name;
    if (modes[m].mode == ws::RectificationMode::kAuto) {
      EXPECT_EQ(rect.mode, ws::RectificationMode::kLatLon);
    }
  }
}

}  // namespace
