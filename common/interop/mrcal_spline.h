// mrcal's LENSMODEL_SPLINED_STEREOGRAPHIC_order=3_Nx=.._Ny=.._fov_x_deg=..
// (mrcal 2.2, "lensmodels"), evaluated here and checked against mrcal's own
// mrcal.project in tests/interop:
//
//   u = 2 tan(theta / 2) (X, Y) / rho = (X, Y) 2 / (|p| + Z)   (stereographic)
//   q = (fx, fy) (u + delta(u)) + (cx, cy)
//
// delta is a uniform cubic B-spline surface, one (dx, dy) control point per
// knot: Nx x Ny knots spaced h = 2 u_edge / (Nx - 3) apart and centred on
// u = 0, u_edge = 2 tan(fov_x / 4) (the stereographic u of fov_x / 2). A
// point in knot segment i (between knots i and i + 1; i clamped to
// [1, N - 3], so that outside the knots the edge segment's polynomial goes
// on) reads the control points i - 1 .. i + 2 with the uniform cubic
// B-spline weights of t = (u - knot_i) / h. Intrinsics: fx, fy, cx, cy,
// then the control points, dx and dy of knot (ix, iy) at
// 2 (iy Nx + ix) + {0, 1}.
//
// As a model class of distortion.h's concept, so that models/projection.h
// projects and inverts it: Coordinate is the stereographic u and Distort
// adds delta; the coefficients are the control points. delta is not radial:
// RadialDistortion is 0, and Undistort's Jacobian check is what finds a fold.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>

#include "models/radial_coordinate.h"
#include "models/scalar_part.h"

namespace ws {

// The stereographic coordinate u of a direction, and back.
struct Stereographic {
  // |u| grows without bound towards straight back; a coordinate for wide
  // fields, like the angle.
  static constexpr double kMaxRadius = TanTheta::kMaxRadius;
  static constexpr bool kAngle = true;
  // False for the zero vector and straight back (|p| + Z = 0).
  template <typename T>
  static bool Ideal(const T* ray, T* ideal) {
    using std::sqrt;
    const T norm = sqrt(ray[0] * ray[0] + ray[1] * ray[1] + ray[2] * ray[2]);
    const T denominator = norm + ray[2];
    if (!(ScalarPart(denominator) > 0.0)) return false;
    ideal[0] = 2.0 * ray[0] / denominator;
    ideal[1] = 2.0 * ray[1] / denominator;
    return true;
  }
  // The unit ray of u: theta = 2 atan(|u| / 2).
  static bool Ray(const double ideal[2], double ray[3]) {
    const double u2 = ideal[0] * ideal[0] + ideal[1] * ideal[1];
    // sin(theta) / |u| = 4 / (4 + |u|^2), cos(theta) = (4 - |u|^2) / (4 + |u|^2)
    ray[0] = 4.0 * ideal[0] / (4.0 + u2);
    ray[1] = 4.0 * ideal[1] / (4.0 + u2);
    ray[2] = (4.0 - u2) / (4.0 + u2);
    return true;
  }
};

struct MrcalSplineConfig {
  int nx = 16, ny = 12;   // knots across and down, at least 4 each
  int fov_x_deg = 200;     // degrees: the field the knots' inner segments span across

  // "LENSMODEL_SPLINED_STEREOGRAPHIC_order=3_Nx=16_Ny=12_fov_x_deg=200".
  std::string LensModel() const;
  // Parses such a name (order 3 only); throws std::invalid_argument otherwise.
  static MrcalSplineConfig Parse(const std::string& lensmodel);
  // The knot spacing h in u.
  double Spacing() const { return 4.0 * std::tan(fov_x_deg * M_PI / 720.0) / (nx - 3); }
};

class MrcalSpline {
 public:
  using Coordinate = Stereographic;

  explicit MrcalSpline(const MrcalSplineConfig& config) : config_(config), h_(config.Spacing()) {}

  const MrcalSplineConfig& config() const { return config_; }
  int NumCoeffs() const { return 2 * config_.nx * config_.ny; }

  template <typename T>
  T RadialDistortion(const T*, const T&) const {
    return T(0.0);
  }

  // p1, p2 are not mrcal's: they are 0 here.
  template <typename T>
  void Distort(const T* c, const T&, const T&, const T& x, const T& y, T* xd, T* yd) const {
    int ix, iy;
    T wx[4], wy[4];
    Weights(x, config_.nx, &ix, wx);
    Weights(y, config_.ny, &iy, wy);
    T dx(0.0), dy(0.0);
    for (int b = 0; b < 4; ++b)
      for (int a = 0; a < 4; ++a) {
        const int k = 2 * ((iy - 1 + b) * config_.nx + ix - 1 + a);
        const T w = wy[b] * wx[a];
        dx += w * c[k];
        dy += w * c[k + 1];
      }
    *xd = x + dx;
    *yd = y + dy;
  }

  // The first control point index (ix - 1 in x) and the four weights of u
  // along one axis of n knots; knot 0 is at -(n - 1) h / 2.
  template <typename T>
  void Weights(const T& u, int n, int* segment, T* w) const {
    const double first = -0.5 * (n - 1) * h_;
    const double at = std::floor((ScalarPart(u) - first) / h_);
    const int i = std::isfinite(at) ? int(std::clamp(at, 1.0, double(n - 3))) : 1;
    const T t = (u - (first + i * h_)) / h_;
    const T t2 = t * t, t3 = t2 * t;
    w[0] = (1.0 - 3.0 * t + 3.0 * t2 - t3) / 6.0;
    w[1] = (3.0 * t3 - 6.0 * t2 + 4.0) / 6.0;
    w[2] = (-3.0 * t3 + 3.0 * t2 + 3.0 * t + 1.0) / 6.0;
    w[3] = t3 / 6.0;
    *segment = i;
  }

 private:
  MrcalSplineConfig config_;
  double h_;
};

}  // namespace ws
