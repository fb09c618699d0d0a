// The calibration cost's Jacobians (calib/solver/residuals.h: each corner
// differentiated by its local coefficients only, the chain rule split at the
// ideal point) against central differences of its own residuals, for every
// block, with the board pose in the camera's frame and via the extrinsic,
// on every test camera, on a spline of 31 coefficients and with a
// non-radial field.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <memory>
#include <numeric>
#include <sstream>

#include "../models/test_cameras.h"
#include "calib/solver/field_blocks.h"
#include "calib/solver/residuals.h"

namespace ws::calib {
namespace {

using ws::testing::TestCamera;
using ws::testing::TestCameras;

// A 5 x 4 board seen obliquely from close by: its corners' ideal radii
// run from near the axis to past 1 (45 degrees), across many knot spans.
ViewPoints Board() {
  ViewPoints points;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 4; ++j) {
      const Eigen::Vector3d X(0.12 * i - 0.3, 0.12 * j - 0.2, 0.0);
      points.Add(X, Eigen::Vector2d(600 + 10 * i, 450 - 7 * j),
                 Eigen::Vector2d(X.x() * X.x() - 0.02, X.y() * X.y() - 0.01));
    }
  return points;
}

void CheckJacobians(const AnyDistortionModel& model, const NonRadialField& field,
                    std::vector<std::vector<double>> blocks, bool via_extrinsic,
                    const std::string& where) {
  std::vector<int> every_segment(size_t(FieldBlocks(field).count()));
  std::iota(every_segment.begin(), every_segment.end(), 0);
  std::unique_ptr<ceres::CostFunction> cost(
      MakeCost(model, field, Board(), via_extrinsic, every_segment));
  const int rows = cost->num_residuals();
  ASSERT_EQ(cost->parameter_block_sizes().size(), blocks.size()) << where;
  std::vector<double*> parameters;
  std::vector<std::vector<double>> jacobians;
  std::vector<double*> jacobian_pointers;
  for (auto& block : blocks) {
    parameters.push_back(block.data());
    jacobians.emplace_back(rows * block.size());
    jacobian_pointers.push_back(jacobians.back().data());
  }
  std::vector<double> residuals(rows), plus(rows), minus(rows), plain(rows);
  ASSERT_TRUE(cost->Evaluate(parameters.data(), residuals.data(), jacobian_pointers.data()))
      << where;
  ASSERT_TRUE(cost->Evaluate(parameters.data(), plain.data(), nullptr)) << where;
  for (int row = 0; row < rows; ++row) EXPECT_NEAR(residuals[row], plain[row], 1e-9) << where;
  for (size_t b = 0; b < blocks.size(); ++b) {
    for (size_t j = 0; j < blocks[b].size(); ++j) {
      const double saved = blocks[b][j];
      const double step = 1e-6 * std::max(1.0, std::abs(saved));
      blocks[b][j] = saved + step;
      ASSERT_TRUE(cost->Evaluate(parameters.data(), plus.data(), nullptr)) << where;
      blocks[b][j] = saved - step;
      ASSERT_TRUE(cost->Evaluate(parameters.data(), minus.data(), nullptr)) << where;
      blocks[b][j] = saved;
      for (int row = 0; row < rows; ++row) {
        const double numeric = (plus[row] - minus[row]) / (2 * step);
        const double automatic = jacobians[b][row * blocks[b].size() + j];
        EXPECT_NEAR(automatic, numeric, 2e-5 * (1 + std::abs(numeric)))
            << where << ": d residual[" << row << "] / d block " << b << "[" << j << "]";
      }
    }
  }
}

// coeffs: the radial model's, then the field's, then the tilt's, split
// into the cost's blocks (residuals.h) after the rig's.
void CheckBothWays(const AnyDistortionModel& model, const std::vector<double>& intrinsics,
                   const std::vector<double>& coeffs, const std::string& name,
                   const NonRadialField& field = NonRadialField()) {
  const std::vector<double> warp{2e-3, -1e-3}, pose{0.25, -0.35, 0.1, 0.02, -0.01, 0.3},
      extrinsic{0.01, 0.02, -0.015, -0.12, 0.002, 0.004};
  const int n = std::visit([](const auto& m) { return m.NumCoeffs(); }, model);
  const std::vector<double> radial(coeffs.begin(), coeffs.begin() + n);
  std::vector<std::vector<double>> parts;
  if (field.tilt()) parts.emplace_back(coeffs.end() - 2, coeffs.end());
  const FieldBlocks blocks(field);
  for (int s = 0; s < blocks.count(); ++s)
    parts.emplace_back(coeffs.begin() + n + blocks.Offset(s),
                       coeffs.begin() + n + blocks.Offset(s) + blocks.Size(s));
  for (const bool via : {false, true}) {
    std::vector<std::vector<double>> all = {intrinsics, radial, warp, pose};
    if (via) all.push_back(extrinsic);
    all.insert(all.end(), parts.begin(), parts.end());
    CheckJacobians(model, field, all, via, name + (via ? ", board via the extrinsic" : ", board in its frame"));
  }
}

class ViewCostJacobians : public ::testing::TestWithParam<TestCamera> {};

TEST_P(ViewCostJacobians, MatchCentralDifferences) {
  const TestCamera& test = GetParam();
  const auto intrinsics = test.model.Intrinsics();
  const AnyDistortionModel model = MakeModel(test.model.distortion, test.which);
  const std::vector<double> coeffs = std::visit(
      [&](const auto& m) { return m.EstimatedCoeffs(test.model.distortion.coeffs); }, model);
  CheckBothWays(model, {intrinsics.begin(), intrinsics.end()}, coeffs, test.name);
}

INSTANTIATE_TEST_SUITE_P(Models, ViewCostJacobians, ::testing::ValuesIn(TestCameras()),
                         [](const auto& info) { return info.param.name; });

// Many knots: a corner reads 4 of 31 coefficients, every span is used.
TEST(ViewCostJacobians, ThirtyOneCoefficientSplineMatchesCentralDifferences) {
  for (const ModelKind kind : {ModelKind::kBspline, ModelKind::kBsplineTheta}) {
    const AnyDistortionModel model = MakeCalibrationModel(kind, CalibrationSetup{1.6, 30, 3});
    std::vector<double> coeffs(31);
    for (size_t i = 0; i < coeffs.size(); ++i) coeffs[i] = 0.02 * std::sin(0.7 * i) - 0.003 * i;
    CheckBothWays(model, {350.2, 344.9, 652.3, 471.8, 4e-4, -3e-4}, coeffs, ModelName(kind) + " 31");
  }
}

// A 7 x 5 field over the board's part of the image on every model (each
// corner reads 16 of its 70 coefficients, and (x_d, y_d) moves the field),
// a sensor tilt (models/sensor_tilt.h: its two angles ride in the Jet) and
// both (the field reads the tilted point).
TEST_P(ViewCostJacobians, WithANonRadialPartMatchCentralDifferences) {
  const TestCamera& test = GetParam();
  const auto intrinsics = test.model.Intrinsics();
  const AnyDistortionModel model = MakeModel(test.model.distortion, test.which);
  const std::vector<double> radial = std::visit(
      [&](const auto& m) { return m.EstimatedCoeffs(test.model.distortion.coeffs); }, model);
  const std::array<double, 4> domain = {-1.2, 1.2, -0.9, 0.9};
  for (const NonRadialField& field : {NonRadialField(7, 5, domain), NonRadialField(0, 0, {}, true),
                                      NonRadialField(7, 5, domain, true)}) {
    std::vector<double> coeffs = radial;
    for (int k = 0; k < field.GridCoeffs(); ++k) coeffs.push_back(2e-3 * std::sin(1.3 * k));
    if (field.tilt()) coeffs.insert(coeffs.end(), {0.012, -0.007});
    CheckBothWays(model, {intrinsics.begin(), intrinsics.end()}, coeffs,
                  test.name + (field.grid() ? " with a field" : "") + (field.tilt() ? " with a tilt" : ""),
                  field);
  }
}

// A view reads a few segments of a fine field (field_blocks.h): the solver
// is given those, and a corner that reads a control point of a segment the
// view was not given fails the evaluation rather than reading a wrong one.
TEST(ViewCostJacobians, AViewIsGivenTheSegmentsItsCornersRead) {
  const AnyDistortionModel model = MakeCalibrationModel(ModelKind::kBspline, CalibrationSetup{1.6, 12, 3});
  const NonRadialField field(16, 12, {-1.6, 1.6, -1.2, 1.2});
  const std::vector<double> intrinsics{350.2, 344.9, 652.3, 471.8, 4e-4, -3e-4};
  std::vector<double> radial(12);
  for (size_t i = 0; i < radial.size(); ++i) radial[i] = 0.01 * std::sin(0.7 * i);
  // The board seen from 1.5 m: a part of the image.
  const std::vector<double> warp{0, 0}, pose{0.25, -0.35, 0.1, 0.02, -0.01, 1.5};
  // The board's corners where the camera sees them (no field).
  ViewPoints board;
  const ViewPoints flat = Board();
  const Eigen::Vector3d omega(pose[0], pose[1], pose[2]);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(omega.norm(), omega.normalized()).toRotationMatrix();
  for (int i = 0; i < flat.size(); ++i) {
    const Eigen::Vector3d X(flat.object[3 * i], flat.object[3 * i + 1], flat.object[3 * i + 2]);
    const Eigen::Vector3d Xc = R * X + Eigen::Vector3d(pose[3], pose[4], pose[5]);
    double pixel[2];
    ASSERT_TRUE(std::visit([&](const auto& m) {
      return Project(m, NonRadialField(), intrinsics.data(), radial.data(), Xc.data(), pixel);
    }, model));
    board.Add(X, Eigen::Vector2d(pixel[0], pixel[1]), Eigen::Vector2d::Zero());
  }
  const std::vector<int> support = FieldSupport(field, intrinsics.data(), board.image);
  const FieldBlocks blocks(field);
  ASSERT_FALSE(support.empty());
  EXPECT_LT(support.size(), size_t(blocks.count()) / 2) << "a small board reads a small part";
  auto evaluate = [&](const std::vector<int>& segments) {
    std::unique_ptr<ceres::CostFunction> cost(MakeCost(model, field, board, false, segments));
    std::vector<std::vector<double>> values = {intrinsics, radial, warp, pose};
    for (int s : segments) values.emplace_back(size_t(blocks.Size(s)), 1e-3);
    std::vector<const double*> parameters;
    for (const auto& v : values) parameters.push_back(v.data());
    std::vector<double> residuals(size_t(cost->num_residuals()));
    return cost->Evaluate(parameters.data(), residuals.data(), nullptr);
  };
  EXPECT_TRUE(evaluate(support));
  // Without the segments the corners read (the support's inner part: all
  // but its margin), the evaluation fails.
  std::vector<int> outer;
  std::vector<char> read(size_t(blocks.count()), 0);
  for (size_t i = 0; i + 1 < board.image.size(); i += 2) {
    double s = (board.image[i] - intrinsics[kCx]) / intrinsics[kFx];
    double t = (board.image[i + 1] - intrinsics[kCy]) / intrinsics[kFy];
    const NonRadialField::Local local = field.LocalBasis(s, t);
    for (int k = 0; k < NonRadialField::kLocal; ++k) read[size_t(blocks.SegmentOf(0, local.index[k]))] = 1;
  }
  for (int s : support)
    if (!read[size_t(s)]) outer.push_back(s);
  EXPECT_FALSE(evaluate(outer));
}

}  // namespace
}  // namespace ws::calib
