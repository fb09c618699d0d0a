#include "models/curve_fit.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <ceres/ceres.h>
#include <Eigen/Dense>

#include "models/bspline_basis.h"
#include "models/distortion_function.h"
#include "models/monotone_cubic.h"

namespace ws {
namespace {

// r'_i - r_i (1 + D(r_i)) for one row.
template <typename Model>
struct HeightResidual {
  template <typename T>
  bool operator()(T const* const* coeffs, T* residual) const {
    const T r(ideal);
    residual[0] = real - r * (1.0 + model->RadialDistortion(coeffs[0], r));
    return true;
  }
  const Model* model;
  double ideal, real;
};

}  // namespace

Distortion FitBsplineByCollocation(const LensTable& table, int degree) {
  const std::vector<double> knots = SchoenbergWhitneyKnots(table.ideal, degree);
  const int n = static_cast<int>(table.ideal.size());
  Eigen::MatrixXd A(n, n);
  for (int i = 0; i < n; ++i)
    A.row(i) = Eigen::RowVectorXd::Map(EvaluateBasis(knots, degree, table.ideal[i]).data(), n);
  const std::vector<double> distortion = TableDistortion(table);
  const Eigen::VectorXd alpha =
      A.partialPivLu().solve(Eigen::VectorXd::Map(distortion.data(), n));
  return BsplineDistortion(knots, degree, Coefficients::kAll).ToData(alpha.data());
}

Distortion FitByLeastSquares(const AnyDistortionModel& any_model, const LensTable& table) {
  return std::visit(
      [&](const auto& model) {
        using Model = std::decay_t<decltype(model)>;
        const int num_coeffs = model.NumCoeffs();
        if (static_cast<int>(table.ideal.size()) < num_coeffs)
          throw std::runtime_error("fitting " + ModelName(Model::kKind) + " needs at least " +
                                   std::to_string(num_coeffs) + " table rows");
        std::vector<double> coeffs(num_coeffs, 0.0);
        ceres::Problem problem;
        for (size_t i = 0; i < table.ideal.size(); ++i) {
          auto* cost = new ceres::DynamicAutoDiffCostFunction<HeightResidual<Model>>(
              new HeightResidual<Model>{&model, table.ideal[i], table.real[i]});
          cost->AddParameterBlock(num_coeffs);
          cost->SetNumResiduals(1);
          problem.AddResidualBlock(cost, nullptr, coeffs.data());
        }
        ceres::Solver::Options options;
        options.linear_solver_type = ceres::DENSE_QR;
        options.max_num_iterations = 200;
        options.function_tolerance = 1e-16;
        options.gradient_tolerance = 1e-16;
        options.parameter_tolerance = 1e-16;
        options.logging_type = ceres::SILENT;
        ceres::Solver::Summary summary;
        ceres::Solve(options, &problem, &summary);
        if (!summary.IsSolutionUsable())
          throw std::runtime_error("fitting " + ModelName(Model::kKind) + " failed: " + summary.message);
        return model.ToData(coeffs.data());
      },
      any_model);
}

FitErrors MeasureFitErrors(const Distortion& fit, const LensTable& table,
                           int samples_per_interval) {
  const DistortionFunction curve(fit);
  FitErrors errors;
  double sum_squares = 0;
  for (size_t i = 0; i < table.ideal.size(); ++i) {
    const double error = curve.DistortedRadius(table.ideal[i]) - table.real[i];
    sum_squares += error * error;
    errors.max_abs = std::max(errors.max_abs, std::abs(error));
  }
  errors.rms = std::sqrt(sum_squares / table.ideal.size());
  const MonotoneCubic reference(table.ideal, table.real);
  for (size_t i = 0; i + 1 < table.ideal.size(); ++i) {
    for (int k = 1; k < samples_per_interval; ++k) {
      const double r =
          table.ideal[i] + (table.ideal[i + 1] - table.ideal[i]) * k / samples_per_interval;
      errors.max_abs_between =
          std::max(errors.max_abs_between, std::abs(curve.DistortedRadius(r) - reference(r)));
    }
  }
  return errors;
}

}  // namespace ws
