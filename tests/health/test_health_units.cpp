// The parts of stereo-health one by one: the refinement's rectified rows
// against the rectification stereo-match builds, the verdict's hysteresis,
// the refinement and its guard rails on exact synthetic matches, the
// message's checks and its line on stereo-status.
#include <gtest/gtest.h>

#include <random>

#include "health/extrinsic_refine.h"
#include "health/rectified_dy_residual.h"
#include "health/verdict.h"
#include "health_fixtures.h"
#include "lcm_io/decode.h"
#include "monitor/status_board.h"
#include "rectify/rectification.h"
#include "sim/sim_config.h"

namespace {

using namespace ws::test;

ws::Rig SimRig() {
  const ws::SimConfig sim = ws::DefaultSimConfig(0.5);
  ws::Rig rig;
  rig.left = sim.left;
  rig.right = sim.right;
  rig.T = Eigen::Vector3d(-0.3, 0, 0);
  return rig;
}

// Rays of random points 1-5 m in front of the rig, in both camera frames,
// with where they land in `rect`'s left image.
std::vector<ws::RayMatch> ExactMatches(const ws::Rig& truth, const ws::Rectification& rect, int n) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> lateral(-1.2, 1.2), depth(1, 5);
  std::vector<ws::RayMatch> matches;
  while (int(matches.size()) < n) {
    const double z = depth(rng);
    const Eigen::Vector3d X(lateral(rng) * z, 0.8 * lateral(rng) * z, z);
    const Eigen::Vector3d Xr = truth.R * X + truth.T;
    const cv::Vec3d p = rect.R_left * cv::Vec3d(X.x(), X.y(), X.z());
    const cv::Point2f pixel(float(rect.f * p[0] / p[2] + rect.cx), float(rect.f * p[1] / p[2] + rect.cy));
    if (!(Xr.z() > 0.5) || pixel.x < 0 || pixel.y < 0 || pixel.x >= rect.size.width || pixel.y >= rect.size.height)
      continue;
    matches.push_back({cv::Vec3d(X.x(), X.y(), X.z()), cv::Vec3d(Xr.x(), Xr.y(), Xr.z()), pixel});
  }
  return matches;
}

TEST(RectifiedDy, RowsAreThoseOfTheRectificationStereoMatchBuilds) {
  ws::Rig rig = RightCameraTurned(SimRig(), Eigen::Vector3d(0.3, -1, 0.5), 1.5);
  rig.T += Eigen::Vector3d(0, 0.01, -0.02);
  const ws::Rectification rect = ws::BuildRectification(rig);
  double om[3];
  ceres::RotationMatrixToAngleAxis(rig.R.data(), om);  // column-major, as Eigen stores it
  const Eigen::Vector3d t = rig.T.normalized();
  for (const cv::Vec3d& ray : {cv::Vec3d(0, 0, 1), cv::Vec3d(0.8, -0.6, 1), cv::Vec3d(-1.5, 1.1, 1)}) {
    const cv::Vec3d pl = rect.R_left * ray, pr = rect.R_right * ray;
    double y_l, y_r;
    ws::RectifiedRows(om, t.data(), ray.val, ray.val, &y_l, &y_r);
    EXPECT_NEAR(y_l, pl[1] / pl[2], 1e-12);
    EXPECT_NEAR(y_r, pr[1] / pr[2], 1e-12);
  }
}

std::vector<ws::DyMatch> Frame(int n, float dy) {
  std::vector<ws::DyMatch> m;
  for (int i = 0; i < n; ++i) m.push_back({cv::Point2f(float(10 * i % 640), float(7 * i % 480)), dy});
  return m;
}

TEST(VerdictWindow, OneBadFrameDoesNotFlipItAndTooFewMatchesAreUnknown) {
  ws::VerdictWindow w{ws::VerdictOptions{}};  // max 0.3 px, window 5, confirm 3, 25 matches
  const ws::DyGrid grid;
  const cv::Size size(640, 480);
  EXPECT_EQ(w.Add(Frame(100, 0.05f), grid, size), "unknown");
  EXPECT_EQ(w.Add(Frame(100, 0.05f), grid, size), "unknown");
  EXPECT_EQ(w.Add(Frame(100, 0.05f), grid, size), "ok");
  EXPECT_EQ(w.Add(Frame(100, 2.0f), grid, size), "ok") << "one bad frame";
  EXPECT_EQ(w.Add(Frame(100, 0.05f), grid, size), "ok");
  EXPECT_EQ(w.Add(Frame(100, 2.0f), grid, size), "ok");
  EXPECT_EQ(w.Add(Frame(100, 2.0f), grid, size), "ok") << "the newest three still disagree";
  EXPECT_EQ(w.Add(Frame(100, 2.0f), grid, size), "misaligned");
  EXPECT_EQ(w.Add(Frame(10, 0.0f), grid, size), "misaligned") << "a frame of 10 matches does not count";
  for (int i = 0; i < 3; ++i) w.Add(Frame(10, 0.0f), grid, size);
  EXPECT_EQ(w.verdict(), "unknown") << "fewer than 3 usable frames among the last 5";
  EXPECT_EQ(w.usable_frames(), 1);
}

TEST(RefineExtrinsics, RecoversTheTrueRotationFromExactMatches) {
  const ws::Rig truth = SimRig();
  const ws::Rig pitched = RightCameraTurned(truth, Eigen::Vector3d::UnitX(), 0.5);
  const ws::Rectification rect = ws::BuildRectification(pitched);
  const auto matches = ExactMatches(truth, rect, 500);
  const ws::RefineResult r = ws::RefineExtrinsics(pitched, rect.f, matches, rect.size, {}, {});
  ASSERT_TRUE(r.applied) << r.refused;
  EXPECT_LT(RotationAngleDeg(r.rig.R, truth.R), 1e-6);
  EXPECT_LT((r.rig.T - truth.T).norm(), 1e-8);
  EXPECT_GT(r.dy_median_before, 0.5);
  EXPECT_LT(r.dy_median_after, 1e-6);
  EXPECT_NEAR(r.rotation_change_deg, 0.5, 1e-6);
}

TEST(RefineExtrinsics, RefusesTooFewTooClusteredOrTooLargeCorrections) {
  const ws::Rig truth = SimRig();
  const ws::Rig pitched = RightCameraTurned(truth, Eigen::Vector3d::UnitX(), 3);
  const ws::Rectification rect = ws::BuildRectification(pitched);
  auto matches = ExactMatches(truth, rect, 500);
  ws::RefineResult r = ws::RefineExtrinsics(pitched, rect.f, matches, rect.size, {}, {});
  EXPECT_FALSE(r.applied);
  EXPECT_NE(r.refused.find("larger than 2.000 deg"), std::string::npos) << r.refused;
  EXPECT_EQ(r.rig.R, pitched.R) << "nothing changed";

  r = ws::RefineExtrinsics(pitched, rect.f, {matches.begin(), matches.begin() + 100}, rect.size, {}, {});
  EXPECT_FALSE(r.applied);
  EXPECT_NE(r.refused.find("100 matches, fewer than the 300"), std::string::npos) << r.refused;

  for (auto& m : matches) m.pixel = cv::Point2f(5, 5);  // all in one region
  r = ws::RefineExtrinsics(pitched, rect.f, matches, rect.size, {}, {});
  EXPECT_FALSE(r.applied);
  EXPECT_NE(r.refused.find("not spread enough"), std::string::npos) << r.refused;
}

widestereo::calibration_health_t HealthMessage() {
  widestereo::calibration_health_t h{};
  h.verdict = "misaligned";
  h.max_dy_px = 0.3;
  h.dy_median_px = 1.234;
  h.dy_p95_px = 2.5;
  h.matches = 800;
  h.frames = 3;
  h.grid_rows = 1;
  h.grid_cols = 2;
  h.grid_dy_px = {{-1.0, 1.0}};
  h.grid_matches = {{400, 400}};
  return h;
}

template <class Msg>
void Decode(const Msg& msg) {
  std::vector<uint8_t> bytes(size_t(msg.getEncodedSize()));
  msg.encode(bytes.data(), 0, int(bytes.size()));
  ws::DecodeMessage<Msg>(bytes.data(), int(bytes.size()));
}

TEST(CalibrationHealthMessage, DecoderChecksItAndStereoStatusShowsIt) {
  EXPECT_NO_THROW(Decode(HealthMessage()));
  auto bad = HealthMessage();
  bad.verdict = "fine";
  EXPECT_THROW(Decode(bad), ws::DecodeError);
  bad = HealthMessage();
  bad.dy_median_px = NAN;
  EXPECT_THROW(Decode(bad), ws::DecodeError);
  bad = HealthMessage();
  bad.grid_matches[0][1] = -1;
  EXPECT_THROW(Decode(bad), ws::DecodeError);

  ws::StatusBoard board;
  board.Add(HealthMessage());
  const std::string table = board.Render(0);
  EXPECT_NE(table.find("health: misaligned"), std::string::npos) << table;
  EXPECT_NE(table.find("median |dy| 1.234 px"), std::string::npos) << table;
}

}  // namespace
