#include "models/distortion_function.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace ws {

DistortionFunction::DistortionFunction(const Distortion& data)
    : model_(MakeModel(data, Coefficients::kAll)),
      coeffs_(std::visit([&](const auto& model) { return model.EstimatedCoeffs(data.coeffs); },
                         model_)) {
  for (size_t i = 0; i < coeffs_.size(); ++i)
    if (!std::isfinite(coeffs_[i]))
      throw std::invalid_argument(ModelName(data.kind) + " coefficient " + std::to_string(i) +
                                  " is not finite");
}

double DistortionFunction::operator()(double r) const {
  return std::visit([&](const auto& model) { return model.RadialDistortion(coeffs_.data(), r); },
                    model_);
}

}  // namespace ws
