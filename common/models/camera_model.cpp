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
      distortion_(model_.distortion) {
  if (!HasTangential(distortion_.model()) && (model_.p1 != 0 || model_.p2 != 0))
    throw std::invalid_argument(model_.distortion.kind + " has no tangential terms: p1 = p2 = 0");
}

std::optional<Eigen::Vector2d> Camera::Project(const Eigen::Vector3d& point) const {
  Eigen::Vector2d pixel;
  const bool in_front = std::visit(
      [&](const auto& model) {
        return ws::Project(model, intrinsics_.data(), distortion_.coeffs(), point.data(),
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
        return ws::Unproject(model, intrinsics_.data(), distortion_.coeffs(), pixel.data(),
                             ray.data());
      },
      distortion_.model());
  if (!found) return std::nullopt;
  return ray;
}

}  // namespace ws
