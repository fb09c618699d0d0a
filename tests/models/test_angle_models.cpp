// The angle models (kb4, bspline_theta): Kannala-Brandt exactly as
// cv::fisheye computes it, and both models' round trips over the whole field
// of a 200-degree lens, rays beyond 90 degrees included.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <ceres/jet.h>
#include <Eigen/Geometry>
#include <opencv2/calib3d.hpp>

#include "models/camera_model.h"
#include "models/fisheye_lens.h"
#include "models/radial_coordinate.h"
#include "opencv_fisheye.h"
#include "test_cameras.h"

namespace ws {
namespace {

using testing::Kb4Camera;

Eigen::Vector3d Direction(double theta, double phi) {
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

double AngleBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

TEST(Kb4, ProjectsExactlyAsOpenCvFisheye) {
  const CameraModel model = Kb4Camera();
  const Camera camera(model);
  std::mt19937 random(5);
  std::uniform_real_distribution<double> theta(0, 89 * M_PI / 180), phi(-M_PI, M_PI),
      depth(0.1, 20);
  std::vector<cv::Point3d> points;
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Vector3d X = depth(random) * Direction(theta(random), phi(random));
    points.emplace_back(X.x(), X.y(), X.z());
  }
  points.emplace_back(0, 0, 1);  // on the axis
  const cv::Matx33d K(model.fx, 0, model.cx, 0, model.fy, model.cy, 0, 0, 1);
  EXPECT_LT(test::WorstGapToOpenCvFisheye(camera, points, K, model.distortion.coeffs), 1e-9);
}

TEST(Kb4, HasNoTangentialTerms) {
  CameraModel model = Kb4Camera();
  model.p1 = 1e-4;
  EXPECT_THROW(Camera{model}, std::invalid_argument);
}

class AngleModelRoundTrip : public ::testing::TestWithParam<CameraModel> {};

// Every direction up to 100 degrees off axis (a 200-degree field).
TEST_P(AngleModelRoundTrip, UnprojectOfProjectReturnsEveryRay) {
  const Camera camera(GetParam());
  double worst = 0;
  for (double deg = 0; deg <= 100; deg += 0.5)
    for (double phi = -M_PI; phi < M_PI; phi += M_PI / 16) {
      const Eigen::Vector3d ray = Direction(deg * M_PI / 180, phi);
      const auto pixel = camera.Project(3.7 * ray);
      ASSERT_TRUE(pixel) << deg << " deg";
      const auto back = camera.Unproject(*pixel);
      ASSERT_TRUE(back) << deg << " deg";
      EXPECT_NEAR(back->norm(), 1.0, 1e-15);
      worst = std::max(worst, AngleBetween(*back, ray));
    }
  EXPECT_LT(worst, 1e-9);
}

TEST_P(AngleModelRoundTrip, ProjectOfUnprojectReturnsEveryPixelOfTheImageCircle) {
  const Camera camera(GetParam());
  const CameraModel& m = GetParam();
  // The circle of 100 degrees, along the x axis.
  const double circle = camera.Project(Direction(100 * M_PI / 180, 0))->x() - m.cx;
  int beyond_90 = 0;
  double worst = 0;
  for (double v = 0; v < m.image_height; v += 8)
    for (double u = 0; u < m.image_width; u += 8) {
      const Eigen::Vector2d pixel(u, v);
      if (std::hypot((u - m.cx) / m.fx, (v - m.cy) / m.fy) * m.fx > circle) continue;
      const auto ray = camera.Unproject(pixel);
      ASSERT_TRUE(ray) << pixel.transpose();
      beyond_90 += ray->z() < 0;
      worst = std::max(worst, (*camera.Project(*ray) - pixel).norm());
    }
  EXPECT_LT(worst, 1e-6);
  EXPECT_GT(beyond_90, 100) << "pixels whose rays point backwards";
}

INSTANTIATE_TEST_SUITE_P(Models, AngleModelRoundTrip,
                         ::testing::Values(Kb4Camera(), FisheyeKneeCamera()),
                         [](const auto& info) { return ModelName(info.param.distortion.kind); });

TEST(FisheyeKneeLens, TheCameraFollowsItsCurve) {
  const CameraModel model = FisheyeKneeCamera();
  const Camera camera(model);
  const LensTable table = FisheyeKneeLensTable();
  double worst_px = 0;
  for (size_t i = 1; i < table.ideal.size(); ++i) {
    const double theta = table.ideal[i];
    const double r_d = theta * (1 + camera.DistortionCurve(theta));
    worst_px = std::max(worst_px, model.fx * std::abs(r_d - table.real[i]));
  }
  std::printf("bspline_theta fit of the knee lens: worst %.2g px\n", worst_px);
  EXPECT_LT(worst_px, 0.005);
  EXPECT_TRUE(camera.IsAngleModel());
  const double circle = camera.Project({std::sin(100 * M_PI / 180), 0, std::cos(100 * M_PI / 180)})->x() - model.cx;
  EXPECT_LT(circle, model.image_height / 2.0) << "the 200-degree image circle fits the image";
}

TEST(ThetaCoordinate, IsSmoothOnTheAxis) {
  using Jet = ceres::Jet<double, 3>;
  // d(theta X / rho)/dX = 1 / Z on the axis, d/dY = 0.
  const Jet ray[3] = {Jet(0.0, 0), Jet(0.0, 1), Jet(2.0, 2)};
  Jet ideal[2];
  ASSERT_TRUE(Theta::Ideal(ray, ideal));
  EXPECT_DOUBLE_EQ(ideal[0].a, 0.0);
  EXPECT_DOUBLE_EQ(ideal[0].v[0], 0.5);
  EXPECT_DOUBLE_EQ(ideal[0].v[1], 0.0);
  EXPECT_DOUBLE_EQ(ideal[1].v[1], 0.5);
  const double back[3] = {0, 0, -1};
  double none[2];
  EXPECT_FALSE(Theta::Ideal(back, none)) << "straight back has no direction";
  const double behind[3] = {1, 0, -1};  // 135 degrees
  ASSERT_TRUE(Theta::Ideal(behind, none));
  EXPECT_NEAR(none[0], 0.75 * M_PI, 1e-15);
}

}  // namespace
}  // namespace ws
