// The non-radial part of a camera model: a smooth 2-D correction of the
// distorted normalized point before it becomes a pixel,
//
//   (x_f, y_f) = (x_d, y_d) + F(x_d, y_d),      u = fx x_f + cx,  v = fy y_f + cy,
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
// then the y components at cols rows + j cols + i. A calibration keeps F free
// of what the other parameters already describe (calib/nonradial_prior.h).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "models/bspline_basis.h"
#include "models/scalar_part.h"

namespace ws {

// The stored field: grid, rectangle and coefficients (cols = 0: none).
struct NonRadial {
  int cols = 0, rows = 0;
  std::array<double, 4> domain{};  // s0, s1, t0, t1
  std::vector<double> coeffs;      // 2 cols rows, as above
  bool empty() const { return cols == 0; }
};

class NonRadialField {
 public:
  static constexpr int kDegree = 3;
  static constexpr int kLocal = (kDegree + 1) * (kDegree + 1);  // control points per point
  static constexpr int kMaxControlPoints = 64;                    // a side
  static constexpr int kMaxCoeffs = 2 * kMaxControlPoints * kMaxControlPoints;

  NonRadialField() = default;  // none: F = 0
  // Throws std::invalid_argument unless cols, rows are both 0 (none) or both
  // at least kDegree + 1 (and at most kMaxControlPoints), and the rectangle is finite and
  // not empty.
  NonRadialField(int cols, int rows, const std::array<double, 4>& domain);
  static NonRadialField FromData(const NonRadial& data) {
    return NonRadialField(data.cols, data.rows, data.domain);
  }

  bool empty() const { return cols_ == 0; }
  int cols() const { return cols_; }
  int rows() const { return rows_; }
  const std::array<double, 4>& domain() const { return domain_; }
  int NumCoeffs() const { return 2 * cols_ * rows_; }
  // "field_x_3_2" (component, column i, row j).
  std::string CoeffName(int k) const;
  NonRadial ToData(const double* coeffs) const;

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
    if (empty()) return;
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

  // Solves m = p + F(p) for p by Newton's method from p = m; false when it
  // does not converge (to 1e-12) in 30 steps or I + dF/dp is not positive
  // definite in the determinant at an iterate (the field folds there).
  bool Invert(const double* coeffs, const double m[2], double p[2]) const;

 private:
  template <typename T>
  static T Clamp(const T& v, double lo, double hi) {
    if (ScalarPart(v) < lo) return T(lo);
    if (ScalarPart(v) > hi) return T(hi);
    return v;
  }

  int cols_ = 0, rows_ = 0;
  std::array<double, 4> domain_{};
  std::vector<double> knots_s_, knots_t_;
};

}  // namespace ws
