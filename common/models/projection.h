// Projection of a camera-frame direction through any camera model (paper
// Eqs. 12-15 for the pinhole models), and its inverse, the unit ray of a pixel.
//
//   (x, y) = Model::Coordinate::Ideal(X, Y, Z)    radial_coordinate.h:
//                                                 (X, Y) / Z, or theta (X, Y) / rho
//   (x_d, y_d) = model.Distort(coeffs, p1, p2, x, y)   (distortion.h)
//   (x_t, y_t) = TiltPoint(tau, (x_d, y_d))            (sensor_tilt.h; (x_d, y_d) without one)
//   (x_f, y_f) = (x_t, y_t) + F(x_t, y_t)              (nonradial_field.h; F = 0 without one)
//   u = fx x_f + cx,  v = fy y_f + cy
//
// Intrinsics are the array {fx, fy, cx, cy, p1, p2} (indices kFx..kP2), the
// coefficients a separate array: model.NumCoeffs() of the radial model, then
// field.NumCoeffs() of the non-radial part (F's, then the tilt's); one parameter block each in a
// Ceres problem. Everything is templated on the scalar so that Ceres can
// differentiate it automatically.
#pragma once

#include <cmath>
#include <vector>

#include <ceres/jet.h>

#include "models/intrinsics.h"
#include "models/nonradial_field.h"
#include "models/radial_coordinate.h"
#include "models/scalar_part.h"

namespace ws {

// The distorted normalized point (x_d, y_d) of the ideal point (x, y).
template <typename Model, typename T>
void DistortIdeal(const Model& model, const T* intrinsics, const T* coeffs, const T* ideal,
                  T* distorted) {
  model.Distort(coeffs, intrinsics[kP1], intrinsics[kP2], ideal[0], ideal[1], &distorted[0],
                &distorted[1]);
}

// The pixel of a point (x_f, y_f) of the normalized plane.
template <typename T>
void ToPixel(const T* intrinsics, const T* normalized, T* pixel) {
  pixel[0] = intrinsics[kFx] * normalized[0] + intrinsics[kCx];
  pixel[1] = intrinsics[kFy] * normalized[1] + intrinsics[kCy];
}

// The pixel of the ideal point (x, y): Project after the coordinate.
template <typename Model, typename T>
void ProjectIdeal(const Model& model, const NonRadialField& field, const T* intrinsics,
                  const T* coeffs, const T* ideal, T* pixel) {
  T d[2], p[2];
  DistortIdeal(model, intrinsics, coeffs, ideal, d);
  field.Apply(coeffs + model.NumCoeffs(), d, p);
  ToPixel(intrinsics, p, pixel);
}

// Projects the camera-frame point (or direction) X to the pixel uv; false
// (uv untouched) where the model's coordinate has no ideal point for it
// (pinhole models: Z <= 0; angle models: straight back).
template <typename Model, typename T>
bool Project(const Model& model, const NonRadialField& field, const T* intrinsics,
             const T* coeffs, const T* point, T* pixel) {
  T ideal[2];
  if (!Model::Coordinate::Ideal(point, ideal)) return false;
  ProjectIdeal(model, field, intrinsics, coeffs, ideal, pixel);
  return true;
}

// Solves model.Distort(x, y) = distorted for the ideal normalized point.
//
// Newton's method from (x, y) = distorted (the distortion is small relative to
// r), with the 2x2 Jacobian from the model's own templated code (Jets), each
// step halved until the residual decreases. It succeeds when the residual is
// below 1e-12 (1 + |distorted|), which puts the point within about that of
// the root. It fails, rather than return a wrong point, when the Jacobian
// determinant is not positive at an iterate (the map folds there and has no
// unique inverse), when no step decreases the residual, after 50 iterations,
// and when the radial map r -> r (1 + D(r)) is not increasing at 16 evenly
// spaced radii up to the solution's (a solution past a fold), and when the
// solution's radius is not below the coordinate's largest (pi for an angle).
template <typename Model>
bool Undistort(const Model& model, const double* coeffs, double p1, double p2,
               const double distorted[2], double ideal[2]) {
  using Jet = ceres::Jet<double, 2>;
  const std::vector<Jet> jet_coeffs(coeffs, coeffs + model.NumCoeffs());
  const Jet jet_p1(p1), jet_p2(p2);
  struct Iterate {
    double x, y, residual[2], jacobian[4], norm;
  };
  auto evaluate = [&](double x, double y) {
    Jet xd, yd;
    model.Distort(jet_coeffs.data(), jet_p1, jet_p2, Jet(x, 0), Jet(y, 1), &xd, &yd);
    const double ex = xd.a - distorted[0], ey = yd.a - distorted[1];
    return Iterate{x, y, {ex, ey}, {xd.v[0], xd.v[1], yd.v[0], yd.v[1]}, std::hypot(ex, ey)};
  };
  const double tolerance = 1e-12 * (1.0 + std::hypot(distorted[0], distorted[1]));
  Iterate it = evaluate(distorted[0], distorted[1]);
  for (int iteration = 0;; ++iteration) {
    const double* J = it.jacobian;
    const double det = J[0] * J[3] - J[1] * J[2];
    if (!(det > 0.0) || !std::isfinite(it.norm)) return false;
    if (it.norm <= tolerance) break;
    if (iteration == 50) return false;
    const double step[2] = {-(J[3] * it.residual[0] - J[1] * it.residual[1]) / det,
                            -(J[0] * it.residual[1] - J[2] * it.residual[0]) / det};
    for (double t = 1.0;; t *= 0.5) {
      if (t < 1e-9) return false;
      const Iterate trial = evaluate(it.x + t * step[0], it.y + t * step[1]);
      if (trial.norm < it.norm) {
        it = trial;
        break;
      }
    }
  }
  const double r = std::hypot(it.x, it.y);
  if (!(r < Model::Coordinate::kMaxRadius)) return false;
  for (int k = 1; k <= 16; ++k) {
    const Jet rk(r * k / 16.0, 0);
    const Jet height = rk * (1.0 + model.RadialDistortion(jet_coeffs.data(), rk));
    if (!(height.v[0] > 0.0)) return false;
  }
  ideal[0] = it.x;
  ideal[1] = it.y;
  return true;
}

// The ideal point of a pixel: the non-radial part inverted (NonRadialField::Invert),
// then the distortion (Undistort); false where either fails.
template <typename Model>
bool IdealOfPixel(const Model& model, const NonRadialField& field, const double* intrinsics,
                  const double* coeffs, const double pixel[2], double ideal[2]) {
  const double normalized[2] = {(pixel[0] - intrinsics[kCx]) / intrinsics[kFx],
                                (pixel[1] - intrinsics[kCy]) / intrinsics[kFy]};
  double distorted[2];
  return field.Invert(coeffs + model.NumCoeffs(), normalized, distorted) &&
         Undistort(model, coeffs, intrinsics[kP1], intrinsics[kP2], distorted, ideal);
}

// The unit ray (X, Y, Z) that projects to the pixel (Z > 0 for the pinhole
// models; any direction for the angle models); false when IdealOfPixel fails.
template <typename Model>
bool Unproject(const Model& model, const NonRadialField& field, const double* intrinsics,
               const double* coeffs, const double pixel[2], double ray[3]) {
  double ideal[2];
  return IdealOfPixel(model, field, intrinsics, coeffs, pixel, ideal) &&
         Model::Coordinate::Ray(ideal, ray);
}

}  // namespace ws
