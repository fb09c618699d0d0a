// The paper's flat-wall reconstruction (Sec. VII-C, issue #6): the simulator
// renders a random-dot wall 2.0 m in front of the ~125 deg mustache-lens rig
// (0.3 m baseline); stereo-capture -> stereo-match -> stereo-cloud, as
// processes over file:// logs, must give back a flat wall at the right
// distance over most of the field with the rig's B-spline calibration, and a
// measurably worse one with a poly6 calibration of the same rig.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "match_fixtures.h"
#include "test_support.h"
#include "wall_chain.h"

namespace {

using namespace ws::test;

constexpr int kFrames = 2;
constexpr const char* kNumDisparities = "64";  // the wall is at 52 px

class FlatWall : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new std::string(TempDir("flat-wall"));
    truth_ = new ws::SimTruth(CaptureWall(*dir_, "config/sim/wall.yaml", kFrames));
  }
  static void TearDownTestSuite() {
    delete truth_;
    delete dir_;
  }

  // The wall chain (wall_chain.h) with stereo-match's settings from
  // `match_config`, then `match_args`, and stereo-cloud's from `cloud_config`.
  static WallRun Run(const ws::Rig& rig, const std::string& name,
                     const std::vector<std::string>& match_args = {},
                     const std::string& match_config = "config/stereo-match.yaml",
                     const std::string& cloud_config = "config/stereo-cloud.yaml", double focal_scale = 1.0) {
    WallChainOptions options;
    options.focal_scale = focal_scale;
    options.match_args = match_args;
    options.match_config = match_config;
    options.cloud_config = cloud_config;
    return RunWallChain(*dir_, *truth_, rig, name, kFrames, kNumDisparities, options);
  }

  static std::string* dir_;
  static ws::SimTruth* truth_;
};

std::string* FlatWall::dir_ = nullptr;
ws::SimTruth* FlatWall::truth_ = nullptr;

TEST_F(FlatWall, BsplineCalibrationGivesAFlatWallAtTwoMetresAndPoly6IsWorse) {
  const ws::Rig rig = truth_->rig;
  const WallRun bspline = Run(rig, "bspline");
  const WallRun poly6 = Run(RigFittedAs(rig, "poly6"), "poly6");
  ASSERT_EQ(bspline.wall.size(), size_t(kFrames));
  ASSERT_EQ(poly6.wall.size(), size_t(kFrames));

  // The disparity noise dd: the matcher's, measured here as the scatter of
  // the B-spline run's disparities about the true ones. Its rectification is
  // exact (the calibration is the truth), so all of it is the matcher's; the
  // poly6 run matches the very same images.
  double dd = 0;
  for (const auto& d : bspline.disparity) dd = std::max(dd, d.sigma);
  EXPECT_LT(dd, 0.1) << "SGBM's sub-pixel noise on the rendered dots";
  const ws::Rectification rect = ws::BuildRectification(rig);
  const double z = truth_->frames.front().wall_distance;
  ASSERT_NEAR(z, 2.0, 1e-12);
  const double predicted = z * z * dd / (rect.f * rect.baseline);  // dz = z^2 dd / (f B)
  std::printf("[ wall ] dd = %.4f px, f = %.2f px, B = %.3f m, z = %.1f m: predicted dz = %.2f mm\n", dd,
              rect.f, rect.baseline, z, 1000 * predicted);

  for (int i = 0; i < kFrames; ++i) {
    const WallFit& b = bspline.wall[size_t(i)];
    const WallFit& p = poly6.wall[size_t(i)];
    std::printf("[ wall ] frame %d: plane-fit RMS bspline %.2f mm (%.2f x predicted), poly6 %.2f mm (%.2f x); "
                "distance error bspline %+.3f %%, poly6 %+.3f %%; coverage bspline %.3f, poly6 %.3f; "
                "RMS to the true wall bspline %.2f mm, poly6 %.2f mm\n",
                i, 1000 * b.inlier_rms, b.inlier_rms / predicted, 1000 * p.inlier_rms, p.inlier_rms / predicted,
                100 * (b.offset / z - 1), 100 * (p.offset / z - 1), b.coverage, p.coverage,
                1000 * b.rms_to_truth, 1000 * p.rms_to_truth);
    // B-spline: as flat as the disparity noise allows, at 2.0 m, over most
    // of the field both cameras see.
    EXPECT_LT(b.inlier_rms, 2 * predicted);
    EXPECT_GT(b.inlier_rms, predicted / 2);
    EXPECT_NEAR(b.offset, z, 0.005 * z);
    EXPECT_LT(b.tilt_rad, 1e-3);
    EXPECT_GT(b.coverage, 0.9);
    EXPECT_GT(b.inlier_fraction, 0.99);
    EXPECT_GT(bspline.disparity[size_t(i)].density, 0.9);
    // poly6: the same images give a wall that is not flat (beyond what the
    // noise explains), farther from the truth, and over less of the field.
    EXPECT_GT(p.inlier_rms, 2 * predicted);
    EXPECT_GT(p.inlier_rms, 3 * b.inlier_rms);
    EXPECT_GT(p.rms_to_truth, 5 * b.rms_to_truth);
    EXPECT_LT(p.coverage, b.coverage - 0.2);
  }
}

// The accuracy cost of the fast matcher modes (docs/depth.md, "Matcher modes"): the
// same wall, the exact calibration, each mode against full SGBM.
TEST_F(FlatWall, FastMatcherModesKeepTheWallAtTwoMetres) {
  const ws::Rig rig = truth_->rig;
  const double z = truth_->frames.front().wall_distance;
  struct Mode {
    std::string name;
    std::vector<std::string> args;
    std::string match_config = "config/stereo-match.yaml";
    std::string cloud_config = "config/stereo-cloud.yaml";
    double focal_scale = 1.0;
  };
  const std::vector<Mode> modes = {
      {"sgbm", {"--matcher", "sgbm"}},
      {"sgbm3way", {"--matcher", "sgbm3way"}},
      {"bm", {"--matcher", "bm", "--block-size", "15"}},
      {"sgbm3way-d2", {"--matcher", "sgbm3way", "--downscale", "2"}},
      {"live", {}, "config/stereo-match-live.yaml", "config/stereo-cloud-live.yaml"},
      // At focal scale 0.7 the rectified images hold the lenses' field in
      // 968 x 726 of their 1280 x 960 pixels: the common field's region
      // (the default) against the whole image.
      {"live-f0.7", {}, "config/stereo-match-live.yaml", "config/stereo-cloud-live.yaml", 0.7},
      {"live-f0.7-whole", {"--whole-image"}, "config/stereo-match-live.yaml", "config/stereo-cloud-live.yaml", 0.7}};
  std::vector<WallRun> runs;
  for (const Mode& mode : modes) {
    runs.push_back(Run(rig, mode.name, mode.args, mode.match_config, mode.cloud_config, mode.focal_scale));
    ASSERT_EQ(runs.back().wall.size(), size_t(kFrames)) << mode.name;
  }
  for (size_t m = 0; m < modes.size(); ++m) {
    const WallFit& w = runs[m].wall[0];
    const DisparityErrors& d = runs[m].disparity[0];
    std::printf("[ mode ] %-12s density %.3f, sigma %.3f px, bad %.4f | plane RMS %.2f mm, distance error "
                "%+.3f %%, coverage %.3f, RMS to the true wall %.2f mm\n",
                modes[m].name.c_str(), d.density, d.sigma, d.bad_rate, 1000 * w.inlier_rms,
                100 * (w.offset / z - 1), w.coverage, 1000 * w.rms_to_truth);
    // Every mode finds the wall where it is, over most of the field; none
    // is flatter than full SGBM by more than chance, and none is more than
    // a few times less flat.
    EXPECT_NEAR(w.offset, z, 0.01 * z) << modes[m].name;
    EXPECT_GT(w.coverage, 0.7) << modes[m].name;
    EXPECT_GT(d.density, 0.6) << modes[m].name;
    EXPECT_LT(w.inlier_rms, 10 * runs[0].wall[0].inlier_rms) << modes[m].name;
  }
  // Matching only the common field's region finds the same wall as
  // matching the whole image.
  const WallRun& region = runs[modes.size() - 2];
  const WallRun& whole = runs.back();
  EXPECT_NEAR(region.disparity[0].density, whole.disparity[0].density, 0.005);
  EXPECT_NEAR(region.wall[0].coverage, whole.wall[0].coverage, 0.005);
  EXPECT_NEAR(region.wall[0].inlier_rms, whole.wall[0].inlier_rms, 0.05 * whole.wall[0].inlier_rms);
  EXPECT_NEAR(region.wall[0].offset, whole.wall[0].offset, 1e-4 * z);
}

}  // namespace
