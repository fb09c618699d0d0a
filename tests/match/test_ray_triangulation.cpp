// Triangulation from rays (rectify/ray_triangulation.h): a point seen by both
// cameras, rectified, comes back from its disparity, for pinhole and
// lat-lon rectification (beyond 90 degrees off axis too for lat-lon).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "match_fixtures.h"
#include "rectify/ray_triangulation.h"
#include "sim/simulator.h"

namespace {

using namespace ws::test;

// Points at 0.5-10 m in random directions of the left rectified frame that
// both cameras image: each triangulated from its rectified disparity.
// Returns how many were checked.
int CheckRoundTrip(const ws::Rig& rig, ws::RectificationMode mode, double max_theta) {
  const ws::Rectification rect = ws::BuildRectification(rig, {1.0, {}, mode});
  const ws::Camera left(rig.left), right(rig.right);
  const cv::Matx33d R = [&] {
    cv::Matx33d m;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) m(r, c) = rig.R(r, c);
    return m;
  }();
  const cv::Vec3d T(rig.T(0), rig.T(1), rig.T(2));
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1, 1), range(0.5, 10);
  int checked = 0;
  for (int k = 0; k < 4000; ++k) {
    cv::Vec3d dir(unit(random), unit(random), unit(random));
    dir /= cv::norm(dir);
    const cv::Vec3d P = range(random) * dir;  // left rectified frame
    const cv::Vec3d X_left = rect.R_left.t() * P, X_right = R * X_left + T;
    if (std::acos(X_left[2] / cv::norm(X_left)) > max_theta ||
        std::acos(X_right[2] / cv::norm(X_right)) > max_theta)
      continue;
    const auto pl = left.Project({X_left[0], X_left[1], X_left[2]});
    const auto pr = right.Project({X_right[0], X_right[1], X_right[2]});
    if (!pl || !pr) continue;
    cv::Point2d l, r;
    if (!ws::RectifyPoint(rect, rig, true, {(*pl)[0], (*pl)[1]}, &l) ||
        !ws::RectifyPoint(rect, rig, false, {(*pr)[0], (*pr)[1]}, &r))
      continue;
    EXPECT_NEAR(l.y, r.y, 1e-6);
    const auto X = ws::TriangulateDisparity(rect, l.x, l.y, l.x - r.x);
    if (!X) continue;  // near an epipole the two rays are parallel
    EXPECT_LT(cv::norm(*X - P), 1e-6 * cv::norm(P)) << "point " << P;
    ++checked;
  }
  return checked;
}

TEST(RayTriangulation, PinholeAndLatLonGiveThePointBack) {
  const ws::Rig demo = ws::Simulator(ws::LoadSimConfig("config/sim/default.yaml")).Truth().rig;
  const ws::Rig fisheye = ws::Simulator(ws::LoadSimConfig("config/sim/fisheye.yaml")).Truth().rig;
  EXPECT_GT(CheckRoundTrip(demo, ws::RectificationMode::kPinhole, M_PI / 3), 200);
  EXPECT_GT(CheckRoundTrip(demo, ws::RectificationMode::kLatLon, M_PI / 3), 200);
  EXPECT_GT(CheckRoundTrip(fisheye, ws::RectificationMode::kLatLon, M_PI * 100 / 180), 500);
  // Only the lat-lon image holds points past 90 degrees.
  EXPECT_GT(CheckRoundTrip(fisheye, ws::RectificationMode::kLatLon, M_PI * 100 / 180),
            CheckRoundTrip(fisheye, ws::RectificationMode::kLatLon, M_PI / 2));
}

// The range-accuracy formula against the triangulation itself: the range
// change of a small disparity change, over each image.
TEST(RayTriangulation, RangeChangeIsTheTriangulationsDerivative) {
  const ws::Rig fisheye = ws::Simulator(ws::LoadSimConfig("config/sim/fisheye.yaml")).Truth().rig;
  for (const ws::RectificationMode mode : {ws::RectificationMode::kPinhole, ws::RectificationMode::kLatLon}) {
    const ws::Rectification rect = ws::BuildRectification(fisheye, {1.0, {}, mode});
    int checked = 0;
    for (int v = 10; v < rect.size.height; v += 97)
      for (int u = 40; u < rect.size.width; u += 89)
        for (const double d : {2.0, 10.0, 30.0}) {
          const auto near = ws::TriangulateDisparity(rect, u, v, d), far = ws::TriangulateDisparity(rect, u, v, d - 1e-4);
          if (!near || !far) continue;
          const double numeric = (cv::norm(*far) - cv::norm(*near)) / 1e-4 * 0.1;
          EXPECT_NEAR(ws::RangeChange(rect, u, v, d), numeric, 1e-3 * numeric)
              << ws::RectificationModeName(mode) << " (" << u << ", " << v << ") d " << d;
          ++checked;
        }
    EXPECT_GT(checked, 100) << ws::RectificationModeName(mode);
  }
  // Pinhole, centre row: dZ = Z^2 / (f b) per pixel.
  const ws::Rectification pinhole = ws::BuildRectification(fisheye);
  const double z = pinhole.f * pinhole.baseline / 20;
  EXPECT_NEAR(ws::RangeChange(pinhole, pinhole.cx, pinhole.cy, 20, 1), z * z / (pinhole.f * pinhole.baseline), 1e-9);
  EXPECT_TRUE(std::isnan(ws::RangeChange(pinhole, 10, 10, 0)));
}

TEST(RayTriangulation, PinholeIsFbOverD) {
  const ws::Rig demo = ws::Simulator(ws::LoadSimConfig("config/sim/default.yaml")).Truth().rig;
  const ws::Rectification rect = ws::BuildRectification(demo);
  const auto X = ws::TriangulateDisparity(rect, 100.5, 700.25, 37.5);
  ASSERT_TRUE(X);
  const double z = rect.f * rect.baseline / 37.5;
  EXPECT_NEAR((*X)[2], z, 1e-12 * z);
  EXPECT_NEAR((*X)[0], (100.5 - rect.cx) * z / rect.f, 1e-12 * z);
  EXPECT_NEAR((*X)[1], (700.25 - rect.cy) * z / rect.f, 1e-12 * z);
  EXPECT_FALSE(ws::TriangulateDisparity(rect, 100, 100, 0));
  EXPECT_FALSE(ws::TriangulateDisparity(rect, 100, 100, -3));
}

}  // namespace
