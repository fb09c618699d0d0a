#include "models/camera_model.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

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
  if (!HasTangential(distortion_.model()) && (model_.p1 != 0 || model_.p2 != 0))
    throw std::invalid_argument(model_.distortion.kind + " has no tangential terms: p1 = p2 = 0");
  const std::vector<double>& field = model_.nonradial.coeffs;
  if (int(field.size()) != field_.NumCoeffs())
    throw std::invalid_argument("the non-radial field has " + std::to_string(field.size()) +
                                " coefficients, its grid " + std::to_string(field_.NumCoeffs()));
  for (double c : field)
    if (!std::isfinite(c)) throw std::invalid_argument("non-finite non-radial field coefficient");
  coeffs_.insert(coeffs_.end(), field.begin(), field.end());
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
  const std::vector<double>& knots = model_.distortion.knots;
  if (knots.empty()) return true;
  const double radius = std::visit(
      [&](const auto& model) {
        return ws::IdealRadius<typename std::decay_t<decltype(model)>::Coordinate>(direction.data());
      },
      distortion_.model());
  return radius <= knots.back();
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
