#include "calib/solver/smoothness_prior.h"

#include <ceres/dynamic_autodiff_cost_function.h>

namespace ws::calib {

void AddSmoothnessPrior(ceres::Problem& problem, const AnyDistortionModel& model, double* coeffs,
                        int block_size, double weight) {
  if (!(weight > 0)) return;
  std::visit(
      [&](const auto& spline) {
        if constexpr (kIsBspline<std::decay_t<decltype(spline)>>) {
          const int n = spline.NumBasis();
          auto* cost = new ceres::DynamicAutoDiffCostFunction<SecondDifferenceResidual>(
              new SecondDifferenceResidual{n, weight});
          cost->AddParameterBlock(block_size);
          cost->SetNumResiduals(n - 2);
          problem.AddResidualBlock(cost, nullptr, coeffs);
        }
      },
      model);
}

}  // namespace ws::calib
