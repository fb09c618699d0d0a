// A complete camera: image size, intrinsics, tangential terms and a radial
// distortion model, as stored in calibration files and messages
// (CameraModel), and ready to use in double (Camera).
//
//   pinhole models (bspline, poly6, poly12):  x = X/Z, y = Y/Z      (Z > 0)
//   angle models (kb4, bspline_theta):        (x, y) = theta (X, Y) / rho,
//       rho = sqrt(X^2 + Y^2), theta = atan2(rho, Z)   (radial_coordinate.h)
//   r = sqrt(x^2 + y^2)
//   x_d = (1 + D(r)) x + 2 p1 x y + p2 (r^2 + 2 x^2)
//   y_d = (1 + D(r)) y + p1 (r^2 + 2 y^2) + 2 p2 x y
//   (x_f, y_f) = (x_d, y_d) + F(x_d, y_d)
//   u = fx x_f + cx,  v = fy y_f + cy
//
// D(r) is given by distortion.kind: bspline_distortion.h, poly_distortion.h
// (kb4 has p1 = p2 = 0); F, the non-radial field, by nonradial
// (nonradial_field.h; none: F = 0).
// Pixel coordinates have (0, 0) at the centre of the top-left pixel.
#pragma once

#include <array>
#include <optional>

#include <Eigen/Core>

#include "models/distortion.h"
#include "models/distortion_function.h"
#include "models/intrinsics.h"
#include "models/nonradial_field.h"

namespace ws {

struct CameraModel {
  int image_width = 0;
  int image_height = 0;
  double fx = 0, fy = 0, cx = 0, cy = 0;  // pixels
  double p1 = 0, p2 = 0;                  // tangential distortion
  Distortion distortion;                  // D(r), with r in normalized coordinates
  NonRadial nonradial;                    // F; empty: none

  // {fx, fy, cx, cy, p1, p2}, indexed by kFx..kP2 (intrinsics.h).
  std::array<double, kNumIntrinsics> Intrinsics() const { return {fx, fy, cx, cy, p1, p2}; }
};

class Camera {
 public:
  // Throws std::invalid_argument unless the image size and focal lengths are
  // positive, every number is finite and the distortion is consistent
  // (a model without tangential terms has p1 = p2 = 0; a field has its
  // grid's number of finite coefficients).
  explicit Camera(CameraModel model);

  const CameraModel& model() const { return model_; }

  // The pixel of a camera-frame point or direction; nullopt where the model
  // has none (pinhole models: Z <= 0; angle models: straight back).
  std::optional<Eigen::Vector2d> Project(const Eigen::Vector3d& point) const;
  // The unit ray seen at a pixel (Z > 0 for pinhole models; beyond 90
  // degrees too for angle models); nullopt when the distortion cannot be
  // inverted there (see Undistort in projection.h).
  std::optional<Eigen::Vector3d> Unproject(const Eigen::Vector2d& pixel) const;
  // D(r), the radial distortion curve: r'/r - 1 without the tangential terms
  // (r = tan(theta), or theta for angle models).
  double DistortionCurve(double r) const { return distortion_(r); }
  bool IsAngleModel() const { return Traits(model_.distortion.kind).angle; }
  // Whether a camera-frame direction lies in the field the model describes:
  // its ideal radius (radial_coordinate.h) up to a B-spline's last knot (the
  // calibrated field, times a margin; past it the last cubic piece goes on
  // untamed); for the polynomials, which keep no knots, a direction imaged
  // inside the image before the radial map folds (docs/models.md).
  bool InField(const Eigen::Vector3d& direction) const;

 private:
  CameraModel model_;
  std::array<double, kNumIntrinsics> intrinsics_;
  DistortionFunction distortion_;
  NonRadialField field_;
  std::vector<double> coeffs_;  // the distortion's, then the field's (projection.h)
};

}  // namespace ws
