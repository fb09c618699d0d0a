// The polynomial radial distortion models:
//
//   D(r) = k_1 r^2 + k_2 r^4 + ... + k_N r^{2N}
//
// over the ideal normalized radius r = tan(theta) (Brown; paper Eqs. 16-19):
//   "poly6" (N = 3) and "poly12" (N = 6), with p1, p2;
// over the incidence angle r = theta (radial_coordinate.h):
//   "kb4" (N = 4), Kannala-Brandt exactly as cv::fisheye defines it,
//   theta_d = theta (1 + k1 theta^2 + k2 theta^4 + k3 theta^6 + k4 theta^8),
//   (u, v) = (fx theta_d X / rho + cx, fy theta_d Y / rho + cy): no
//   tangential terms (p1 = p2 = 0) and no skew, so that K and D = (k1..k4)
//   are cv::fisheye's.
// Stored data (Distortion): degree 0, no knots, coefficients k_1..k_N. All of
// them are estimated: D(0) = D'(0) = 0 holds for any k, so Coefficients makes
// no difference. The polynomial is defined for every r, so it needs no
// extrapolation rule; it does fold back (r' decreasing) beyond its fitted
// range when the leading coefficient is negative, which Unproject reports.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "models/distortion.h"
#include "models/model_kind.h"
#include "models/radial_coordinate.h"
#include "models/radial_tangential.h"

namespace ws {

template <int N, class RadialCoordinate = TanTheta>
class PolyDistortion {
 public:
  static_assert(N >= 1, "a polynomial model needs at least k1");
  using Coordinate = RadialCoordinate;
  static constexpr ModelKind kKind = Coordinate::kAngle ? ModelKind::kKb4 : N == 3 ? ModelKind::kPoly6 : ModelKind::kPoly12;
  static_assert(Traits(kKind).terms == N && Traits(kKind).angle == Coordinate::kAngle,
                "a polynomial model of model_kind.h's table");
  static constexpr bool kTangential = Traits(kKind).tangential;

  static PolyDistortion FromData(const Distortion& data, Coefficients) {
    if (data.degree != 0 || !data.knots.empty())
      throw std::invalid_argument(ModelName(kKind) + " takes neither a degree nor knots");
    return PolyDistortion();
  }
  static PolyDistortion ForCalibration(const CalibrationSetup&) { return PolyDistortion(); }

  int NumCoeffs() const { return N; }
  std::string CoeffName(int i) const { return Traits(kKind).coeff_key + std::to_string(i + 1); }

  Distortion ToData(const double* coeffs) const {
    return Distortion{kKind, 0, {}, std::vector<double>(coeffs, coeffs + N)};
  }
  std::vector<double> EstimatedCoeffs(const std::vector<double>& stored) const {
    if (static_cast<int>(stored.size()) != N)
      throw std::invalid_argument(ModelName(kKind) + " needs " + std::to_string(N) + " coefficients, got " +
                                  std::to_string(stored.size()));
    return stored;
  }

  template <typename T>
  T RadialDistortion(const T* k, const T& r) const {
    return OfSquaredRadius(k, r * r);
  }

  template <typename T>
  void Distort(const T* k, const T& p1, const T& p2, const T& x, const T& y, T* xd, T* yd) const {
    RadialTangential(OfSquaredRadius(k, x * x + y * y), p1, p2, x, y, xd, yd);
  }

  // Every coefficient acts at every radius (distortion.h).
  static constexpr int kMaxLocalCoeffs = N;
  int NumLocalCoeffs() const { return N; }
  int FirstLocalCoeff(double, double) const { return 0; }

 private:
  // D as a polynomial in r^2 (Horner's rule): smooth in x and y, no sqrt.
  template <typename T>
  static T OfSquaredRadius(const T* k, const T& r2) {
    T sum = k[N - 1];
    for (int i = N - 2; i >= 0; --i) sum = k[i] + r2 * sum;
    return r2 * sum;
  }
};

using Kb4Distortion = PolyDistortion<4, Theta>;  // "kb4"

}  // namespace ws
