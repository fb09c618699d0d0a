// A camera of another tool's lens model (opencv_lens.h, mrcal_spline.h):
// a model class of distortion.h's concept with its coefficients, projected
// and inverted by models/projection.h (with no non-radial field), so that
// the Newton inverse and its fold checks are widestereo's own.
#pragma once

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "interop/camera_projection.h"
#include "models/projection.h"

namespace ws {

template <class Model>
class ForeignCamera final : public CameraProjection {
 public:
  // intrinsics: {fx, fy, cx, cy, p1, p2} (projection.h); coeffs: the model's
  // NumCoeffs(). Throws std::invalid_argument for a wrong count, a size or
  // focal length that is not positive, or a number that is not finite.
  ForeignCamera(std::string name, int width, int height, Model model,
                const std::array<double, kNumIntrinsics>& intrinsics, std::vector<double> coeffs)
      : name_(std::move(name)), width_(width), height_(height), model_(std::move(model)),
        intrinsics_(intrinsics), coeffs_(std::move(coeffs)) {
    if (int(coeffs_.size()) != model_.NumCoeffs())
      throw std::invalid_argument(name_ + ": " + std::to_string(model_.NumCoeffs()) +
                                  " coefficients expected, got " + std::to_string(coeffs_.size()));
    if (width_ <= 0 || height_ <= 0) throw std::invalid_argument(name_ + ": image size not positive");
    if (!(intrinsics_[kFx] > 0) || !(intrinsics_[kFy] > 0))
      throw std::invalid_argument(name_ + ": focal lengths not positive");
    for (double value : intrinsics_)
      if (!std::isfinite(value)) throw std::invalid_argument(name_ + ": intrinsics not finite");
    for (double value : coeffs_)
      if (!std::isfinite(value)) throw std::invalid_argument(name_ + ": coefficients not finite");
  }

  int image_width() const override { return width_; }
  int image_height() const override { return height_; }
  std::string Name() const override { return name_; }
  std::optional<Eigen::Vector2d> Project(const Eigen::Vector3d& point) const override {
    Eigen::Vector2d pixel;
    if (!ws::Project(model_, NonRadialField(), intrinsics_.data(), coeffs_.data(), point.data(), pixel.data()))
      return std::nullopt;
    return pixel;
  }
  std::optional<Eigen::Vector3d> Unproject(const Eigen::Vector2d& pixel) const override {
    Eigen::Vector3d ray;
    if (!ws::Unproject(model_, NonRadialField(), intrinsics_.data(), coeffs_.data(), pixel.data(), ray.data()))
      return std::nullopt;
    return ray;
  }
  // The field such a model describes keeps no record of where it was
  // calibrated: as for widestereo's polynomials, a direction imaged inside
  // the image, once (its pixel unprojects back to it: not past a fold).
  bool InField(const Eigen::Vector3d& direction) const override {
    const auto pixel = Project(direction);
    if (!pixel || !((*pixel)[0] >= -0.5 && (*pixel)[1] >= -0.5 && (*pixel)[0] <= width_ - 0.5 &&
                    (*pixel)[1] <= height_ - 0.5))
      return false;
    const auto back = Unproject(*pixel);
    return back && (*back - direction.normalized()).norm() < 1e-6;
  }

 private:
  std::string name_;
  int width_, height_;
  Model model_;
  std::array<double, kNumIntrinsics> intrinsics_;
  std::vector<double> coeffs_;
};

}  // namespace ws
