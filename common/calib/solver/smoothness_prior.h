// The smoothness prior that keeps a calibrated B-spline tame where the board
// corners are thin (the paper's Figs. 8-9 show curves that run away past the
// last observed radius).
//
// One residual per interior coefficient of the FULL alpha vector (alpha_0 =
// alpha_1 = 0 included, fixed by the identifiable model):
//
//   e_i = w (alpha_{i-1} - 2 alpha_i + alpha_{i+1}),   i = 1 .. n-2
//
// On uniform knots a second difference of alpha is h^2 B''(r) up to O(h^3),
// so the prior pulls towards a spline that continues linearly. Its weight is
// in pixels,
//
//   w = lambda * fx * r_max,
//
// fx * r_max being about how far (pixels) a unit change of D moves a corner
// at the edge of the field. With the default lambda = 0.01, a second
// difference that would move edge corners by 1 px costs as much as one
// corner 0.01 px off: nothing against the hundreds of corners that pin alpha
// where there are data (on the synthetic rigs the RMS changes by < 0.5 %),
// but it decides the spans that no corner reaches, so the covariance exists
// and the curve continues smoothly past the last observed radius.
// Polynomial models get no prior (their coefficients are global).
#pragma once

#include <ceres/problem.h>

#include "models/model_registry.h"

namespace ws::calib {

// w = lambda * fx * r_max (pixels).
inline double SmoothnessWeight(double lambda, double fx, double r_max) {
  return lambda * fx * r_max;
}

// The prior's residuals over the estimated coefficients alpha_2..alpha_{n-1}
// of an identifiable spline with n basis functions.
struct SecondDifferenceResidual {
  int num_basis;
  double weight;

  template <typename T>
  bool operator()(T const* const* parameters, T* residuals) const {
    const T* estimated = parameters[0];
    auto alpha = [&](int k) { return k < 2 ? T(0.0) : estimated[k - 2]; };
    for (int i = 1; i <= num_basis - 2; ++i)
      residuals[i - 1] = weight * (alpha(i - 1) - 2.0 * alpha(i) + alpha(i + 1));
    return true;
  }
};

// Adds the prior on `coeffs` (a block of `block_size`, the model's
// coefficients first) when `model` is a B-spline and weight > 0.
void AddSmoothnessPrior(ceres::Problem& problem, const AnyDistortionModel& model, double* coeffs,
                        int block_size, double weight);

}  // namespace ws::calib
