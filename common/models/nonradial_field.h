// The non-radial part of a camera model: where the lens needs them, a
// sensor tilt (sensor_tilt.h) and a smooth 2-D correction F of the
// distorted normalized point before it becomes a pixel,
//
//   (x_t, y_t) = TiltPoint(tau, (x_d, y_d))     (none: (x_d, y_d))
//   (x_f, y_f) = (x_t, y_t) + F(x_t, y_t),      u = fx x_f + cx,  v = fy y_f + cy,
//
//   F(s, t) = sum_{j < rows} sum_{i < cols} c_ij N_i(s) M_j(t),    c_ij in R^2,
//
// N_i, M_j the clamped uniform cubic B-spline bases (bspline_basis.h) of
// cols, rows control points over the rectangle [s0, s1] x [t0, t1] of the
// distorted normalized plane (the image with a margin, fixed when the field
// is set up). Outside the rectangle F is its value at the nearest point of
// it. A radial model bends every ray about the principal point; F takes up
// what no radial curve can: a tilted sensor, a decentred element, glass that
// is not quite symmetric (Schops et al., "Why having 10,000 parameters in
// your camera model is better than twelve", CVPR 2020; mrcal's
// LENSMODEL_SPLINED_STEREOGRAPHIC is such a field over a whole lens).
// It lies in the distorted plane, which is the image's up to fx, fy, cx,
// cy, so that its control points are spread evenly over the pixels where
// corners are, and inverting it is a few Newton steps.
//
// Coefficients: 2 cols rows numbers, the x components c^x_ij at j cols + i,
// then the y components at cols rows + j cols + i; then, with a tilt,
// tau_x and tau_y. A calibration keeps F free of what the other parameters
// (the tilt's included) already describe (calib/solver/nonradial_prior.h).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "models/bspline_basis.h"
#include "models/scalar_part.h"
#include "models/sensor_tilt.h"

namespace ws {

// The stored non-radial part: the field's grid, rectangle and coefficients
// (cols = 0: no field) and the sensor tilt (0, 0: none).
struct NonRadial {
  int cols = 0, rows = 0;
  std::array<double, 4> domain{};  // s0, s1, t0, t1
  std::vector<double> coeffs;      // 2 cols rows, as above
  std::array<double, 2> tilt{};    // tau_x, tau_y, radians
  bool tilted() const { return tilt[0] != 0 || tilt[1] != 0; }
  bool empty() const { return cols == 0 && !tilted(); }
};

class NonRadialField {
 public:
  static constexpr int kDegree = 3;
  static constexpr int kLocal = (kDegree + 1) * (kDegree + 1);  // control points per point
  static constexpr int kMaxControlPoints = 64;                    // a side
  static constexpr int kMaxCoeffs = 2 * kMaxControlPoints * kMaxControlPoints;

  NonRadialField() = default;  // none: F = 0, no tilt
  // Throws std::invalid_argument unless cols, rows are both 0 (no field) or
  // both at least kDegree + 1 (and at most kMaxControlPoints), and the
  // rectangle is finite and not empty; `tilt`: tau_x, tau_y follow the grid.
  NonRadialField(int cols, int rows, const std::array<double, 4>& domain, bool tilt = false);
  static NonRadialField FromData(const NonRadial& data) {
    return NonRadialField(data.cols, data.rows, data.domain, data.tilted());
  }

  bool empty() const { return cols_ == 0 && !tilt_; }
  bool grid() const { return cols_ > 0; }  // F is not 0
  bool tilt() const { return tilt_; }
  int cols() const { return cols_; }
  int rows() const { return rows_; }
  const std::array<double, 4>& domain() const { return domain_; }
  int GridCoeffs() const { return 2 * cols_ * rows_; }  // tau_x, tau_y follow these
  int NumCoeffs() const { return GridCoeffs() + (tilt_ ? 2 : 0); }
  // "field_x_3_2" (component, column i, row j); "tilt_x", "tilt_y".
  std::string CoeffName(int k) const;
  // The stored form of the coefficients (NumCoeffs() of them).
  NonRadial ToData(const double* coeffs) const;
  // The coefficients of a stored form with this shape (its grid's, then its
  // tilt's when tilt()).
  std::vector<double> Coeffs(const NonRadial& data) const;

  // The tilted point of the distorted point d: d itself without a tilt.
  template <typename C, typename T>
  void Tilt(const C* coeffs, const T* d, T* tilted) const {
    if (tilt_) {
      TiltPoint(coeffs + GridCoeffs(), d, tilted);
    } else {
      tilted[0] = d[0];
      tilted[1] = d[1];
    }
  }
  // The point (x_f, y_f) of the distorted point d: the tilt, then F.
  template <typename C, typename T>
  void Apply(const C* coeffs, const T* d, T* out) const {
    T t[2], f[2];
    Tilt(coeffs, d, t);
    Evaluate(coeffs, t[0], t[1], f);
    out[0] = t[0] + f[0];
    out[1] = t[1] + f[1];
  }

  // The control points that reach (s, t) and their basis weights N_i(s)
  // M_j(t), with the weights' derivatives by s and t: the x component of
  // control point index[k] is coeffs[index[k]], its y component
  // coeffs[NumCoeffs() / 2 + index[k]].
  struct Local {
    std::array<int, kLocal> index;
    std::array<double, kLocal> weight, by_s, by_t;
  };
  Local LocalBasis(double s, double t) const;

  // F(s, t) into f[2]; T may be a ceres::Jet in the coefficients, in (s, t)
  // or both (the span is chosen on the values).
  template <typename C, typename T>
  void Evaluate(const C* coeffs, const T& s, const T& t, T* f) const {
    f[0] = f[1] = T(0.0);
    if (!grid()) return;
    const T sc = Clamp(s, domain_[0], domain_[1]), tc = Clamp(t, domain_[2], domain_[3]);
    const int span_s = FindSpan(knots_s_, kDegree, ScalarPart(sc));
    const int span_t = FindSpan(knots_t_, kDegree, ScalarPart(tc));
    T ns[kDegree + 1], mt[kDegree + 1];
    NonZeroBasis(knots_s_, kDegree, span_s, sc, ns);
    NonZeroBasis(knots_t_, kDegree, span_t, tc, mt);
    const int half = cols_ * rows_;
    for (int b = 0; b <= kDegree; ++b)
      for (int a = 0; a <= kDegree; ++a) {
        const int k = (span_t - kDegree + b) * cols_ + span_s - kDegree + a;
        const T w = ns[a] * mt[b];
        f[0] += coeffs[k] * w;
        f[1] += coeffs[half + k] * w;
      }
  }

  // Solves m = Apply(p) for the distorted point p: F by Newton's method
  // from m (to 1e-12, at most 30 steps), then the tilt (UntiltPoint); false
  // when Newton does not converge, I + dF/dp is not positive in the
  // determinant at an iterate (the field folds there) or the tilt has no
  // inverse there.
  bool Invert(const double* coeffs, const double m[2], double p[2]) const;

 private:
  template <typename T>
  static T Clamp(const T& v, double lo, double hi) {
    if (ScalarPart(v) < lo) return T(lo);
    if (ScalarPart(v) > hi) return T(hi);
    return v;
  }

  int cols_ = 0, rows_ = 0;
  bool tilt_ = false;
  std::array<double, 4> domain_{};
  std::vector<double> knots_s_, knots_t_;
};

}  // namespace ws
