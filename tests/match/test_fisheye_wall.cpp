// An angle-model calibration downstream (issue #13): the simulator's
// 200-degree fisheye rig (config/sim/fisheye.yaml, its wall scene only)
// through stereo-match (a pinhole rectification of the central field) and
// stereo-cloud with the rig's bspline_theta calibration file: the wall 2.0 m
// in front comes back flat, at its distance, over the field both rectified
// images hold.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cstdio>
#include <fstream>

#include "match_fixtures.h"
#include "rectify/rectification.h"
#include "test_support.h"
#include "wall_chain.h"

namespace {

using namespace ws::test;

// config/sim/fisheye.yaml without its board poses.
std::string WallOnlyConfig(const std::string& dir) {
  YAML::Node config = YAML::LoadFile(SourceDir() + "/config/sim/fisheye.yaml");
  config["scene"].remove("board");
  const std::string path = dir + "/fisheye-wall.yaml";
  std::ofstream(path) << config;
  return path;
}

// The central field at the cameras' resolution (--focal-scale 1, the
// default: 130 x 116 degrees, its edges stretched about 5 times) and
// narrower (1.5: 110 x 94 degrees, less stretch, finer disparities).
TEST(FisheyeWall, BsplineThetaCalibrationGivesTheWallAtTwoMetres) {
  const std::string dir = TempDir("fisheye-wall");
  const ws::SimTruth truth = CaptureWall(dir, WallOnlyConfig(dir), 1);
  const ws::StereoRig rig = RigFromTruth(truth);
  ASSERT_EQ(rig.left.distortion.kind, "bspline_theta");
  const double z = truth.frames.front().wall_distance;
  for (const double focal_scale : {1.0, 1.5}) {
    const std::string name = "bspline_theta-f" + std::to_string(focal_scale).substr(0, 3);
    WallChainOptions options;
    options.focal_scale = focal_scale;
    const WallRun run = RunWallChain(dir, truth, rig, name, 1, "64", options);
    ASSERT_EQ(run.wall.size(), 1u);
    const ws::Rectification rect = ws::BuildRectification(rig, {focal_scale, {}});
    const WallFit& w = run.wall[0];
    std::printf("[ wall ] fisheye, focal scale %.1f: rectified f %.1f px (the central %.0f x %.0f "
                "degrees): plane %.4f m (true %.1f m), RMS %.2f mm, disparity sigma %.3f px, "
                "coverage %.3f\n",
                focal_scale, rect.f, 2 * std::atan(rect.size.width / 2.0 / rect.f) * 180 / M_PI,
                2 * std::atan(rect.size.height / 2.0 / rect.f) * 180 / M_PI, w.offset, z,
                1000 * w.inlier_rms, run.disparity[0].sigma, w.coverage);
    EXPECT_NEAR(w.offset, z, (focal_scale > 1 ? 0.005 : 0.01) * z);
    EXPECT_LT(w.tilt_rad, 0.01);
    EXPECT_GT(w.coverage, 0.85);
    EXPECT_GT(run.disparity[0].density, 0.9);
  }
}

}  // namespace
