#include "models/bspline_distortion.h"

#include <stdexcept>
#include <utility>

namespace ws {

template <class C>
Bspline<C>::Bspline(std::vector<double> knots, int degree, Coefficients which)
    : knots_(std::move(knots)),
      degree_(degree),
      first_estimated_(which == Coefficients::kIdentifiable ? Traits(kKind).gauge_fixed : 0) {
  ValidateKnots(knots_, degree_);
  if (which == Coefficients::kIdentifiable) {
    if (knots_.front() != 0.0 || knots_[degree_] != 0.0)
      throw std::invalid_argument(
          "an identifiable B-spline needs knots clamped at 0 (t_0 = ... = t_K = 0)");
    if (NumBasis() < 3)
      throw std::invalid_argument("an identifiable B-spline needs at least 3 basis functions");
  }
}

template <class C>
Bspline<C> Bspline<C>::FromData(const Distortion& data, Coefficients which) {
  return Bspline(data.knots, data.degree, which);
}

template <class C>
Bspline<C> Bspline<C>::ForCalibration(const CalibrationSetup& setup) {
  return Bspline(UniformClampedKnots(setup.r_max, setup.knot_intervals, setup.degree),
                           setup.degree, Coefficients::kIdentifiable);
}

template <class C>
Distortion Bspline<C>::ToData(const double* coeffs) const {
  Distortion data{kKind, degree_, knots_, std::vector<double>(first_estimated_, 0.0)};
  data.coeffs.insert(data.coeffs.end(), coeffs, coeffs + NumCoeffs());
  return data;
}

template <class C>
std::vector<double> Bspline<C>::EstimatedCoeffs(const std::vector<double>& stored) const {
  if (static_cast<int>(stored.size()) != NumBasis())
    throw std::invalid_argument(ModelName(kKind) + " with " + std::to_string(knots_.size()) +
                                " knots of degree " + std::to_string(degree_) + " needs " +
                                std::to_string(NumBasis()) + " coefficients, got " +
                                std::to_string(stored.size()));
  for (int i = 0; i < first_estimated_; ++i)
    if (stored[i] != 0.0)
      throw std::invalid_argument(Traits(kKind).coeff_key + std::to_string(i) + " = " + std::to_string(stored[i]) +
                                  ", but the identifiable B-spline fixes it at 0");
  return std::vector<double>(stored.begin() + first_estimated_, stored.end());
}

template class Bspline<TanTheta>;
template class Bspline<Theta>;

}  // namespace ws
