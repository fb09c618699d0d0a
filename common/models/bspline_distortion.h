// The B-spline radial distortion models (paper Eqs. 3-6):
//
//   D(r) = B(r) = sum_{i=0}^{n-1} alpha_i N_{i,K}(r)
//
// N_{i,K}: B-spline basis of degree K (default 3) on a FIXED knot vector
// t_0..t_{n+K} (bspline_basis.h). Two kinds, by what r is
// (radial_coordinate.h):
//   "bspline"        r = tan(theta), the ideal normalized radius (the paper's model)
//   "bspline_theta"  r = theta, the incidence angle in radians: the same idea
//                    for fisheye lenses, r_d = theta (1 + B(theta)), rays
//                    beyond 90 degrees included.
// Stored data (Distortion): degree K, the whole knot vector, and all n
// coefficients alpha_0..alpha_{n-1}.
//
// Extrapolation: beyond the last knot (r >= t_n) B continues the polynomial of
// the last non-empty span [t_{n-1}, t_n) (likewise before the first), so
// projection and unprojection are defined over the whole image even when
// r_max was chosen too small.
//
// Two ways of using it (Coefficients):
//  - kAll: every alpha_i is a coefficient. Curve fitting by free collocation
//    (paper Eq. 9) and evaluating any stored model.
//  - kIdentifiable, for calibration: the knots must be clamped at 0
//    (t_0 = ... = t_K = 0), and alpha_0 = alpha_1 = 0 are fixed, not
//    estimated. Then B(0) = alpha_0 = 0 and
//    B'(0) = K (alpha_1 - alpha_0) / t_{K+1} = 0 by construction: the spline
//    cannot trade a constant or a linear term against the focal length.
//    NumCoeffs() = n - 2 and coeffs[j] is alpha_{j+2}; ToData() puts the two
//    zeros back so that stored models are always complete.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "models/bspline_basis.h"
#include "models/distortion.h"
#include "models/model_kind.h"
#include "models/radial_coordinate.h"
#include "models/radial_tangential.h"
#include "models/scalar_part.h"

namespace ws {

template <class RadialCoordinate>
class Bspline {
 public:
  using Coordinate = RadialCoordinate;
  static constexpr ModelKind kKind = Coordinate::kAngle ? ModelKind::kBsplineTheta : ModelKind::kBspline;
  static_assert(Traits(kKind).spline && Traits(kKind).angle == Coordinate::kAngle,
                "a B-spline model of model_kind.h's table");
  static constexpr bool kTangential = Traits(kKind).tangential;  // p1, p2 apply
  // Validates the knots (and, for kIdentifiable, that they start clamped at
  // 0 with at least three basis functions); throws std::invalid_argument.
  Bspline(std::vector<double> knots, int degree, Coefficients which);

  static Bspline FromData(const Distortion& data, Coefficients which);
  // Uniform clamped knots on [0, r_max] with setup.knot_intervals spans,
  // kIdentifiable.
  static Bspline ForCalibration(const CalibrationSetup& setup);

  const std::vector<double>& knots() const { return knots_; }
  int degree() const { return degree_; }
  int NumBasis() const { return NumBasisFunctions(knots_, degree_); }
  int NumCoeffs() const { return NumBasis() - first_estimated_; }
  std::string CoeffName(int i) const { return Traits(kKind).coeff_key + std::to_string(i + first_estimated_); }

  Distortion ToData(const double* coeffs) const;
  // The estimated coefficients of a stored alpha vector; throws if its size
  // is wrong or a gauge-fixed alpha is not zero.
  std::vector<double> EstimatedCoeffs(const std::vector<double>& stored) const;

  // B(r), Eq. 3; the span is chosen on the value of r, the derivatives are
  // those of that span's polynomial. The basis is evaluated on the value r0
  // with its derivative (one dual number) rather than on r's own derivatives:
  // dB = sum_j N_j(r0) d alpha_j + (sum_j alpha_j N_j'(r0)) dr.
  template <typename T>
  T RadialDistortion(const T* coeffs, const T& r) const {
    const double r0 = ScalarPart(r);
    const int span = FindSpan(knots_, degree_, r0);
    double basis[kMaxSplineDegree + 1], slopes[kMaxSplineDegree + 1];
    NonZeroBasisWithSlopes(knots_, degree_, span, r0, basis, slopes);
    T sum(0.0);
    double slope = 0;
    for (int j = 0; j <= degree_; ++j) {
      const int coeff = FirstOfSpan(span) + j;
      if (coeff < 0) continue;
      sum += coeffs[coeff] * basis[j];
      slope += ScalarPart(coeffs[coeff]) * slopes[j];
    }
    return sum + (r - r0) * slope;
  }

  template <typename T>
  void Distort(const T* coeffs, const T& p1, const T& p2, const T& x, const T& y, T* xd,
               T* yd) const {
    RadialTangential(RadialDistortion(coeffs, Radius(x, y)), p1, p2, x, y, xd, yd);
  }

  // Local support (distortion.h): on a span only its degree + 1 basis
  // functions are non-zero, so Distort at (x, y) reads coeffs[first ..
  // first + degree] only (those of them that are estimated).
  static constexpr int kMaxLocalCoeffs = kMaxSplineDegree + 1;
  int NumLocalCoeffs() const { return degree_ + 1; }
  int FirstLocalCoeff(double x, double y) const {
    return FirstOfSpan(FindSpan(knots_, degree_, Radius(x, y)));
  }

 private:
  // r of the ideal point. sqrt has no derivative at 0; there B is flat
  // (kIdentifiable) or has a cone point (kAll) and a zero derivative is the
  // one that is always defined.
  template <typename T>
  static T Radius(const T& x, const T& y) {
    using std::sqrt;
    const T r2 = x * x + y * y;
    return ScalarPart(r2) > 0.0 ? T(sqrt(r2)) : T(0.0);
  }
  // The index into coeffs of alpha_{span - degree}, the first basis function
  // non-zero on the span (negative where it is gauge-fixed).
  int FirstOfSpan(int span) const { return span - degree_ - first_estimated_; }

  std::vector<double> knots_;
  int degree_;
  int first_estimated_;  // alpha index of coeffs[0]: Traits(kKind).gauge_fixed for kIdentifiable, else 0
};

using BsplineDistortion = Bspline<TanTheta>;     // "bspline"
using BsplineThetaDistortion = Bspline<Theta>;   // "bspline_theta"

template <class Model>
inline constexpr bool kIsBspline = false;
template <class Coordinate>
inline constexpr bool kIsBspline<Bspline<Coordinate>> = true;

}  // namespace ws
