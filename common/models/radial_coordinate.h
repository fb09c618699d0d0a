// How a camera model reads a camera-frame direction (X, Y, Z): the ideal
// coordinates (x, y) whose radius r = sqrt(x^2 + y^2) its distortion curve
// D(r) takes, and back. Every model class names one as `Coordinate`.
//
//   TanTheta, the pinhole (bspline, poly6, poly12; paper Eq. 6):
//     (x, y) = (X, Y) / Z,                 r = tan(theta)        Z > 0 only
//   Theta, the angle (kb4, bspline_theta; Kannala & Brandt 2006, Eq. 6):
//     (x, y) = theta (X, Y) / rho,         r = theta
//     rho = sqrt(X^2 + Y^2), theta = atan2(rho, Z) in [0, pi): every
//     direction but straight back, rays beyond 90 degrees included.
//
// theta is the incidence angle: the angle between the ray and the optical
// axis. Under Theta with D = 0 the camera is the equidistant fisheye
// (r_pixels = f theta); under TanTheta with D = 0 it is the pinhole.
#pragma once

#include <cmath>
#include <limits>

#include "models/scalar_part.h"

namespace ws {

struct TanTheta {
  static constexpr bool kAngle = false;
  // The largest radius a direction can have.
  static constexpr double kMaxRadius = std::numeric_limits<double>::infinity();

  // False (ideal untouched) unless Z > 0.
  template <typename T>
  static bool Ideal(const T* ray, T* ideal) {
    if (!(ScalarPart(ray[2]) > 0.0)) return false;
    ideal[0] = ray[0] / ray[2];
    ideal[1] = ray[1] / ray[2];
    return true;
  }

  // The unit ray of ideal coordinates; always true.
  static bool Ray(const double ideal[2], double ray[3]) {
    const double norm = std::sqrt(ideal[0] * ideal[0] + ideal[1] * ideal[1] + 1.0);
    ray[0] = ideal[0] / norm;
    ray[1] = ideal[1] / norm;
    ray[2] = 1.0 / norm;
    return true;
  }
};

struct Theta {
  static constexpr bool kAngle = true;
  static constexpr double kMaxRadius = M_PI;

  // False (ideal untouched) for the zero vector and straight back
  // (rho = 0, Z <= 0), where the direction of (x, y) is undefined.
  template <typename T>
  static bool Ideal(const T* ray, T* ideal) {
    using std::atan2;
    using std::sqrt;
    const T rho2 = ray[0] * ray[0] + ray[1] * ray[1];
    const double z = ScalarPart(ray[2]);
    // theta / rho; near the axis its series in (rho / Z)^2, since sqrt has
    // no derivative at 0: theta / rho = (1 - s / 3 + s^2 / 5) / Z, s = rho^2 / Z^2.
    T scale;
    if (ScalarPart(rho2) > 1e-12 * z * z) {
      const T rho = sqrt(rho2);
      scale = atan2(rho, ray[2]) / rho;
    } else {
      if (!(z > 0.0)) return false;
      const T s = rho2 / (ray[2] * ray[2]);
      scale = (1.0 - s / 3.0 + s * s / 5.0) / ray[2];
    }
    ideal[0] = scale * ray[0];
    ideal[1] = scale * ray[1];
    return true;
  }

  // The unit ray (sin(theta) x / theta, sin(theta) y / theta, cos(theta)),
  // theta = sqrt(x^2 + y^2); false when theta >= pi (no such direction).
  static bool Ray(const double ideal[2], double ray[3]) {
    const double theta = std::hypot(ideal[0], ideal[1]);
    if (!(theta < kMaxRadius)) return false;
    const double sinc = theta > 1e-8 ? std::sin(theta) / theta : 1.0 - theta * theta / 6.0;
    ray[0] = sinc * ideal[0];
    ray[1] = sinc * ideal[1];
    ray[2] = std::cos(theta);
    return true;
  }
};

// The radius r of a camera-frame point under Coordinate; infinity where it
// has none (TanTheta: Z <= 0).
template <class Coordinate>
double IdealRadius(const double* point) {
  double ideal[2];
  if (!Coordinate::Ideal(point, ideal)) return std::numeric_limits<double>::infinity();
  return std::hypot(ideal[0], ideal[1]);
}

}  // namespace ws
