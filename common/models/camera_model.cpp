#include "models/camera_model.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "models/projection.h"

namespace ws {
namespace {

CameraModel Validated(CameraModel model) {
  if (model.image_width <= 0 || model.image_height <= 0)
    throw std::invalid_argument("camera image size must be positive, not " +
                                std::to_string(model.image_width) + "x" +
                                std::to_string(model.image_height));
  if (!(model.fx > 0) || !(model.fy > 0) || !std::isfinite(model.fx) || !std::isfinite(model.fy))
    throw std::invalid_argument("camera focal lengths must be positive and finite");
  for (double value : model.Intrinsics())
    if (!std::isfinite(value)) throw std::invalid_argument("camera intrinsics must be finite");
  return model;
}

}  // namespace

Camera::Camera(CameraModel model)
    : model_(Validated(std::move(model))),
      intrinsics_(model_.Intrinsics()),
      distortion_(model_.distortion),
      field_(NonRadialField::FromData(model_.nonradial)),
      coeffs_(model_.distortion.coeffs) {
  if (!Traits(model_.distortion.kind).tangential && (model_.p1 != 0 || model_.p2 != 0))
    throw std::invalid_argument(ModelName(model_.distortion.kind) + " has no tangential terms: p1 = p2 = 0");
  const std::vector<double>& field = model_.nonradial.coeffs;
  if (int(field.size()) != field_.GridCoeffs())
    throw std::invalid_argument("the non-radial field has " + std::to_string(field.size()) +
                                " coefficients, its grid " + std::to_string(field_.GridCoeffs()));
  for (double c : field)
    if (!std::isfinite(c)) throw std::invalid_argument("non-finite non-radial field coefficient");
  for (double tau : model_.nonradial.tilt)
    if (!(std::abs(tau) < kMaxSensorTilt))
      throw std::invalid_argument("a sensor tilt must be finite and below " +
                                  std::to_string(kMaxSensorTilt) + " rad");
  const std::vector<double> nonradial = field_.Coeffs(model_.nonradial);
  coeffs_.insert(coeffs_.end(), nonradial.begin(), nonradial.end());
}

std::optional<Eigen::Vector2d> Camera::Project(const Eigen::Vector3d& point) const {
  Eigen::Vector2d pixel;
  const bool in_front = std::visit(
      [&](const auto& model) {
        return ws::Project(model, field_, intrinsics_.data(), coeffs_.data(), point.data(),
                           pixel.data());
      },
      distortion_.model());
  if (!in_front) return std::nullopt;
  return pixel;
}

bool Camera::InField(const Eigen::Vector3d& direction) const {
  const double radius = std::visit(
      [&](const auto& model) {
        return ws::IdealRadius<typename std::decay_t<decltype(model)>::Coordinate>(direction.data());
      },
      distortion_.model());
  const std::vector<double>& knots = model_.distortion.knots;
  if (!knots.empty()) return radius <= knots.back();
  // A polynomial: the radial map r -> r (1 + D(r)) rises up to the ray's
  // radius (at 16 radii, as Unproject checks: past a fold two rays share a
  // pixel), and the ray's pixel lies in the image.
  double height = 0;
  for (int k = 1; k <= 16 && radius > 0; ++k) {
    const double r = radius * k / 16.0, next = r * (1.0 + distortion_(r));
    if (!(next > height)) return false;
    height = next;
  }
  const std::optional<Eigen::Vector2d> pixel = Project(direction);
  return pixel && (*pixel)[0] >= -0.5 && (*pixel)[1] >= -0.5 && (*pixel)[0] <= model_.image_width - 0.5 &&
         (*pixel)[1] <= model_.image_height - 0.5;
}

std::optional<Eigen::Vector3d> Camera::Unproject(const Eigen::Vector2d& pixel) const {
  Eigen::Vector3d ray;
  const bool found = std::visit(
      [&](const auto& model) {
        return ws::Unproject(model, field_, intrinsics_.data(), coeffs_.data(), pixel.data(),
                             ray.data());
      },
      distortion_.model());
  if (!found) return std::nullopt;
  return ray;
}

}  // namespace ws
