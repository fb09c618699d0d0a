#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <Eigen/Geometry>
#include <opencv2/calib3d.hpp>

#include "models/camera_model.h"
#include "models/model_registry.h"
#include "test_cameras.h"

namespace ws {
namespace {

using testing::TestCamera;
using testing::TestCameras;

double AngleBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

double DegreesBetween(const Camera& camera, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return AngleBetween(*camera.Unproject(a), *camera.Unproject(b)) * 180 / M_PI;
}

class CameraRoundTrip : public ::testing::TestWithParam<TestCamera> {};

TEST_P(CameraRoundTrip, ProjectOfUnprojectReturnsEveryPixel) {
  const Camera camera(GetParam().model);
  const int width = camera.model().image_width, height = camera.model().image_height;
  for (int v = 0; v <= height; v += 16) {
    for (int u = 0; u <= width; u += 16) {
      const Eigen::Vector2d pixel(u, v);
      const std::optional<Eigen::Vector3d> ray = camera.Unproject(pixel);
      ASSERT_TRUE(ray) << "pixel " << pixel.transpose();
      EXPECT_NEAR(ray->norm(), 1.0, 1e-15);
      const std::optional<Eigen::Vector2d> back = camera.Project(*ray);
      ASSERT_TRUE(back);
      EXPECT_LT((*back - pixel).norm(), 1e-6) << "pixel " << pixel.transpose();
    }
  }
}

TEST_P(CameraRoundTrip, UnprojectOfProjectReturnsTheRayOfEveryPointInView) {
  const Camera camera(GetParam().model);
  const int width = camera.model().image_width, height = camera.model().image_height;
  std::mt19937 random(11);
  std::uniform_real_distribution<double> depth(0.2, 30.0);
  int in_view = 0;
  double worst = 0;
  for (double y = -1.6; y <= 1.6; y += 0.04) {
    for (double x = -2.2; x <= 2.2; x += 0.04) {
      const Eigen::Vector3d point = depth(random) * Eigen::Vector3d(x, y, 1);
      const std::optional<Eigen::Vector2d> pixel = camera.Project(point);
      ASSERT_TRUE(pixel);
      if ((*pixel)[0] < 0 || (*pixel)[0] > width || (*pixel)[1] < 0 || (*pixel)[1] > height)
        continue;
      ++in_view;
      const std::optional<Eigen::Vector3d> ray = camera.Unproject(*pixel);
      ASSERT_TRUE(ray) << "point " << point.transpose();
      worst = std::max(worst, AngleBetween(*ray, point));
    }
  }
  EXPECT_GT(in_view, 5000);  // the grid covers the whole image
  EXPECT_LT(worst, 1e-9);
}

TEST_P(CameraRoundTrip, PointsBehindTheCameraDoNotProject) {
  const Camera camera(GetParam().model);
  EXPECT_FALSE(camera.Project({0.1, 0.2, 0.0}));
  EXPECT_FALSE(camera.Project({0.1, 0.2, -1.0}));
  EXPECT_TRUE(camera.Project({0.0, 0.0, 1e-9}));
}

INSTANTIATE_TEST_SUITE_P(Models, CameraRoundTrip, ::testing::ValuesIn(TestCameras()),
                         [](const auto& info) { return info.param.name; });

TEST(TheiaLikeCamera, HasAbout125DegreesHorizontalField) {
  const Camera camera(TheiaLikeCamera());
  const CameraModel& model = camera.model();
  EXPECT_EQ(model.image_width, 1280);
  EXPECT_EQ(model.image_height, 960);
  EXPECT_NEAR(model.fx, 346.6667, 1e-4);
  EXPECT_EQ(model.cx, 640.0);
  EXPECT_EQ(model.cy, 480.0);
  const double horizontal = DegreesBetween(camera, {0, 480}, {1280, 480});
  const double vertical = DegreesBetween(camera, {640, 0}, {640, 960});
  const double diagonal = DegreesBetween(camera, {0, 0}, {1280, 960});
  std::printf("Theia-like lens: field of view %.2f x %.2f deg, %.2f deg diagonal\n", horizontal,
              vertical, diagonal);
  EXPECT_NEAR(horizontal, 125.0, 0.5);
  EXPECT_NEAR(vertical, 108.0, 1.0);
  EXPECT_NEAR(diagonal, 136.3, 1.0);
  // Its distortion curve is the table's, in normalized radius.
  const LensTable table = TheiaLikeLensTable();
  const std::vector<double> d = TableDistortion(table);
  for (size_t i = 1; i < d.size(); ++i)
    EXPECT_NEAR(camera.DistortionCurve(table.ideal[i] / 1.3), d[i], 1e-9);
}

// The camera projects a grid of points as cv::projectPoints does with the
// distortion vector `dist` and the camera's K.
void ExpectProjectsAsOpenCv(const CameraModel& model, const std::vector<double>& dist) {
  const Camera camera(model);
  std::vector<cv::Point3d> points;
  for (double y = -1.5; y <= 1.5; y += 0.25)
    for (double x = -2.0; x <= 2.0; x += 0.25) points.emplace_back(2 * x, 2 * y, 2.0);
  const cv::Matx33d K(model.fx, 0, model.cx, 0, model.fy, model.cy, 0, 0, 1);
  std::vector<cv::Point2d> expected;
  cv::projectPoints(points, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), K, dist, expected);
  for (size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector2d pixel = *camera.Project({points[i].x, points[i].y, points[i].z});
    EXPECT_NEAR(pixel[0], expected[i].x, 1e-9);
    EXPECT_NEAR(pixel[1], expected[i].y, 1e-9);
  }
}

// poly6 is OpenCV's 5-coefficient model (k1, k2, p1, p2, k3): the same pixels.
TEST(Poly6Camera, ProjectsAsOpenCvDoes) {
  CameraModel model = testing::WithTangential(TheiaLikeCamera());
  model.distortion = {ModelKind::kPoly6, 0, {}, {0.021, -0.0043, 0.00021}};
  ExpectProjectsAsOpenCv(model, {0.021, -0.0043, model.p1, model.p2, 0.00021});
}

// A sensor tilt (models/sensor_tilt.h) is OpenCV's tilted model
// (CALIB_TILTED_MODEL's tauX, tauY): the same pixels; and unprojection
// inverts it, with a field on top, over the whole image.
TEST(TiltedCamera, ProjectsAsOpenCvDoesAndUnprojectsEveryPixel) {
  CameraModel model = testing::WithTangential(TheiaLikeCamera());
  model.distortion = {ModelKind::kPoly6, 0, {}, {0.021, -0.0043, 0.00021}};
  model.nonradial.tilt = {0.02, -0.015};
  std::vector<double> dist(14, 0.0);
  dist[0] = 0.021, dist[1] = -0.0043, dist[2] = model.p1, dist[3] = model.p2, dist[4] = 0.00021;
  dist[12] = model.nonradial.tilt[0], dist[13] = model.nonradial.tilt[1];
  ExpectProjectsAsOpenCv(model, dist);
  model.distortion = TheiaLikeCamera().distortion;
  model.nonradial.cols = model.nonradial.rows = 4;
  model.nonradial.domain = {-2, 2, -1.5, 1.5};
  for (int k = 0; k < 32; ++k) model.nonradial.coeffs.push_back(1e-3 * std::cos(0.7 * k));
  for (const CameraModel& m : {CameraModel(TheiaLikeCamera()), model}) {
    CameraModel tilted = m;
    tilted.nonradial.tilt = {0.02, -0.015};
    const Camera c(tilted);
    for (int v = 0; v <= 960; v += 40)
      for (int u = 0; u <= 1280; u += 40) {
        const std::optional<Eigen::Vector3d> ray = c.Unproject({u, v});
        ASSERT_TRUE(ray) << u << ", " << v;
        EXPECT_LT((*c.Project(*ray) - Eigen::Vector2d(u, v)).norm(), 1e-6) << u << ", " << v;
      }
  }
}

TEST(Unproject, ReportsFailureWhereTheDistortionFolds) {
  CameraModel model = TheiaLikeCamera();
  model.distortion = {ModelKind::kPoly6, 0, {}, {-0.3, 0, 0}};  // r' = r - 0.3 r^3 peaks at r' = 0.70
  const Camera camera(model);
  const std::optional<Eigen::Vector3d> inside = camera.Unproject({640 + 0.5 * model.fx, 480});
  ASSERT_TRUE(inside);
  EXPECT_LT((*camera.Project(*inside) - Eigen::Vector2d(640 + 0.5 * model.fx, 480)).norm(), 1e-6);
  EXPECT_FALSE(camera.Unproject({640 + 0.8 * model.fx, 480}));  // no ideal point maps there
  EXPECT_FALSE(camera.Unproject({640 + 0.8 * model.fx, 480 + 0.3 * model.fy}));
}

TEST(Camera, RejectsInconsistentModels) {
  CameraModel model = TheiaLikeCamera();
  EXPECT_NO_THROW(Camera{model});
  CameraModel bad = model;
  bad.fx = 0;
  EXPECT_THROW(Camera{bad}, std::invalid_argument);
  bad = model;
  bad.image_height = 0;
  EXPECT_THROW(Camera{bad}, std::invalid_argument);
  bad = model;
  bad.p1 = NAN;
  EXPECT_THROW(Camera{bad}, std::invalid_argument);
  bad = model;
  bad.distortion.coeffs.pop_back();
  EXPECT_THROW(Camera{bad}, std::invalid_argument);
  bad = model;
  bad.distortion.coeffs[3] = INFINITY;
  EXPECT_THROW(Camera{bad}, std::invalid_argument);
  bad = model;
  bad.distortion.kind = static_cast<ModelKind>(kNumModelKinds);  // outside the table
  EXPECT_THROW(Camera{bad}, std::invalid_argument);
  bad.distortion = {ModelKind::kPoly6, 3, {}, {0, 0, 0}};
  EXPECT_THROW(Camera{bad}, std::invalid_argument);
}

TEST(ModelRegistry, KnowsEveryModelByKind) {
  EXPECT_EQ(ModelNames(), (std::vector<std::string>{"bspline", "poly6", "poly12", "kb4", "bspline_theta"}));
  const CalibrationSetup setup{2.5, 8, 3};
  for (const auto& [name, num_coeffs] :
       std::vector<std::pair<std::string, int>>{
           {"bspline", 9}, {"poly6", 3}, {"poly12", 6}, {"kb4", 4}, {"bspline_theta", 9}}) {
    const ModelKind kind = ParseModelKind(name);
    EXPECT_EQ(ModelName(kind), name);
    const AnyDistortionModel model = MakeCalibrationModel(kind, setup);
    EXPECT_EQ(KindOf(model), kind);
    std::visit(
        [&, kind = kind, num_coeffs = num_coeffs](const auto& m) {
          EXPECT_EQ(m.kKind, kind);
          EXPECT_EQ(m.NumCoeffs(), num_coeffs) << kind;
          const std::vector<double> coeffs(m.NumCoeffs(), 0.01);
          const Distortion stored = m.ToData(coeffs.data());
          EXPECT_EQ(stored.kind, kind);
          // The table's identifiable coefficients: those stored but the gauge's.
          EXPECT_EQ(stored.coeffs.size(), coeffs.size() + Traits(kind).gauge_fixed) << kind;
          if (!Traits(kind).spline) {
            EXPECT_EQ(Traits(kind).terms, num_coeffs) << kind;
          }
          EXPECT_EQ(m.CoeffName(0).rfind(Traits(kind).coeff_key, 0), 0u) << kind;
          EXPECT_EQ(m.EstimatedCoeffs(stored.coeffs), coeffs);
          // Built back from what was stored, it is the same function.
          const DistortionFunction curve(stored);
          EXPECT_DOUBLE_EQ(curve(1.7), m.RadialDistortion(coeffs.data(), 1.7));
        },
        model);
  }
  try {
    ParseModelKind("fisheye");
    FAIL() << "no error";
  } catch (const std::invalid_argument& error) {
    EXPECT_EQ(std::string(error.what()),
              "unknown distortion model 'fisheye' (known: bspline, poly6, poly12, kb4, "
              "bspline_theta)");
  }
}

}  // namespace
}  // namespace ws
