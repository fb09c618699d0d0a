// Project's automatic derivatives (Ceres Jets through the templated models)
// against central differences of its double version.
#include <gtest/gtest.h>

#include <ceres/dynamic_autodiff_cost_function.h>

#include <cmath>

#include "models/projection.h"
#include "test_cameras.h"

namespace ws {
namespace {

using testing::TestCamera;
using testing::TestCameras;

// The pixel of a point, with intrinsics, coefficients and the point as
// parameter blocks: what a calibration residual differentiates.
template <typename Model>
struct ProjectFunctor {
  template <typename T>
  bool operator()(T const* const* parameters, T* pixel) const {
    return Project(*model, *field, parameters[0], parameters[1], parameters[2], pixel);
  }
  const Model* model;
  const NonRadialField* field;
};

template <typename Model>
void CheckJacobians(const Model& model, const NonRadialField& field,
                    std::vector<std::vector<double>> blocks, const std::string& where) {
  ceres::DynamicAutoDiffCostFunction<ProjectFunctor<Model>> cost(
      new ProjectFunctor<Model>{&model, &field});
  for (const auto& block : blocks) cost.AddParameterBlock(static_cast<int>(block.size()));
  cost.SetNumResiduals(2);
  std::vector<double*> parameters;
  std::vector<std::vector<double>> jacobians;
  std::vector<double*> jacobian_pointers;
  for (auto& block : blocks) {
    parameters.push_back(block.data());
    jacobians.emplace_back(2 * block.size());
    jacobian_pointers.push_back(jacobians.back().data());
  }
  double pixel[2];
  ASSERT_TRUE(cost.Evaluate(parameters.data(), pixel, jacobian_pointers.data())) << where;
  for (size_t b = 0; b < blocks.size(); ++b) {
    for (size_t j = 0; j < blocks[b].size(); ++j) {
      const double saved = blocks[b][j];
      const double step = 1e-6 * std::max(1.0, std::abs(saved));
      double plus[2], minus[2];
      blocks[b][j] = saved + step;
      ASSERT_TRUE(Project(model, field, blocks[0].data(), blocks[1].data(), blocks[2].data(), plus));
      blocks[b][j] = saved - step;
      ASSERT_TRUE(Project(model, field, blocks[0].data(), blocks[1].data(), blocks[2].data(), minus));
      blocks[b][j] = saved;
      for (int row = 0; row < 2; ++row) {
        const double numeric = (plus[row] - minus[row]) / (2 * step);
        const double automatic = jacobians[b][row * blocks[b].size() + j];
        EXPECT_NEAR(automatic, numeric, 1e-6 * (1 + std::abs(numeric)))
            << where << ": d pixel[" << row << "] / d block " << b << "[" << j << "]";
      }
    }
  }
}

class Autodiff : public ::testing::TestWithParam<TestCamera> {};

// Without a non-radial part, with a 6 x 5 field (nonradial_field.h) over
// the image of a camera of about 300 px focal length, and with the field and
// a sensor tilt (sensor_tilt.h).
void CheckPoints(const TestCamera& test, const NonRadialField& field) {
  const auto intrinsics = test.model.Intrinsics();
  std::visit(
      [&](const auto& model) {
        std::vector<double> coeffs = model.EstimatedCoeffs(test.model.distortion.coeffs);
        for (int k = 0; k < field.NumCoeffs(); ++k) coeffs.push_back(2e-3 * std::cos(0.9 * k));
        // On the axis, near it, inside spans, on a knot and (without a field,
        // whose differences would cross it there) beyond the image corner.
        for (const std::vector<double>& point :
             {std::vector<double>{0.0, 0.0, 2.0}, {1e-3, -2e-3, 1.0}, {0.3, 0.2, 1.5},
              {-1.1, 0.7, 0.9}, {1.4, -1.0, 1.0}, {2.3, 1.6, 1.0}}) {
          if (field.grid() && point[0] > 2) continue;
          std::ostringstream where;
          where << test.name << " at (" << point[0] << ", " << point[1] << ", " << point[2] << ")";
          CheckJacobians(model, field, {{intrinsics.begin(), intrinsics.end()}, coeffs, point},
                         where.str() + (field.grid() ? " with a field" : "") +
                             (field.tilt() ? " and a tilt" : ""));
        }
      },
      MakeModel(test.model.distortion, test.which));
}

TEST_P(Autodiff, JacobiansMatchCentralDifferences) {
  CheckPoints(GetParam(), NonRadialField());
  CheckPoints(GetParam(), NonRadialField(6, 5, {-2.1, 2.1, -1.6, 1.6}));
  CheckPoints(GetParam(), NonRadialField(6, 5, {-2.1, 2.1, -1.6, 1.6}, true));
}

INSTANTIATE_TEST_SUITE_P(Models, Autodiff, ::testing::ValuesIn(TestCameras()),
                         [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace ws
