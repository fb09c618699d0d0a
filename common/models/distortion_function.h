// A stored Distortion made ready to evaluate in double: its model class built
// once from the registry, its coefficients checked against it.
#pragma once

#include <vector>

#include "models/distortion.h"
#include "models/model_registry.h"

namespace ws {

class DistortionFunction {
 public:
  // Throws std::invalid_argument for an unknown kind, bad knots or a wrong
  // number of coefficients.
  explicit DistortionFunction(const Distortion& data);

  // D(r) = r'/r - 1, the radial distortion curve (no tangential terms).
  double operator()(double r) const;
  // r' = r (1 + D(r)), the distorted radius.
  double DistortedRadius(double r) const { return r * (1.0 + (*this)(r)); }

  const AnyDistortionModel& model() const { return model_; }
  const double* coeffs() const { return coeffs_.data(); }

 private:
  AnyDistortionModel model_;
  std::vector<double> coeffs_;
};

}  // namespace ws
