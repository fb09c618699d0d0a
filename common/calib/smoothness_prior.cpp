#include "calib/smoothness_prior.h"

#include <ceres/dynamic_autodiff_cost_function.h>

namespace ws::calib {

void AddSmoothnessPrior(ceres::Problem& problem, const AnyDistortionModel& model, double* coeffs,
                        double weight) {
  const auto* spline = std::get_if<BsplineDistortion>(&model);
  if (!spline || !(weight > 0)) return;
  const int n = spline->NumBasis();
  auto* cost = new ceres::DynamicAutoDiffCostFunction<SecondDifferenceResidual>(
      new SecondDifferenceResidual{n, weight});
  cost->AddParameterBlock(spline->NumCoeffs());
  cost->SetNumResiduals(n - 2);
  problem.AddResidualBlock(cost, nullptr, coeffs);
}

}  // namespace ws::calib
