#include "models/nonradial_field.h"

#include <ceres/jet.h>

#include <cmath>
#include <stdexcept>

namespace ws {
namespace {

// Clamped uniform knots over [lo, hi] for n control points of degree K.
std::vector<double> KnotsOver(double lo, double hi, int n, int degree) {
  std::vector<double> knots = UniformClampedKnots(hi - lo, n - degree, degree);
  for (double& k : knots) k += lo;
  return knots;
}

}  // namespace

NonRadialField::NonRadialField(int cols, int rows, const std::array<double, 4>& domain, bool tilt)
    : cols_(cols), rows_(rows), tilt_(tilt), domain_(domain) {
  if (cols == 0 && rows == 0) return;
  auto bad = [](int n) { return n < kDegree + 1 || n > kMaxControlPoints; };
  if (bad(cols) || bad(rows))
    throw std::invalid_argument("a non-radial field needs 4 to 64 control points a side, not " +
                                std::to_string(cols) + " x " + std::to_string(rows));
  for (double v : domain)
    if (!std::isfinite(v)) throw std::invalid_argument("non-finite non-radial field rectangle");
  if (!(domain[1] > domain[0]) || !(domain[3] > domain[2]))
    throw std::invalid_argument("empty non-radial field rectangle");
  knots_s_ = KnotsOver(domain[0], domain[1], cols, kDegree);
  knots_t_ = KnotsOver(domain[2], domain[3], rows, kDegree);
}

std::string NonRadialField::CoeffName(int k) const {
  if (k >= GridCoeffs()) return k == GridCoeffs() ? "tilt_x" : "tilt_y";
  const int half = cols_ * rows_;
  const int j = (k % half) / cols_, i = (k % half) % cols_;
  return std::string(k < half ? "field_x_" : "field_y_") + std::to_string(i) + "_" +
         std::to_string(j);
}

NonRadial NonRadialField::ToData(const double* coeffs) const {
  NonRadial data;
  data.cols = cols_;
  data.rows = rows_;
  data.domain = domain_;
  data.coeffs.assign(coeffs, coeffs + GridCoeffs());
  if (tilt_) data.tilt = {coeffs[GridCoeffs()], coeffs[GridCoeffs() + 1]};
  return data;
}

std::vector<double> NonRadialField::Coeffs(const NonRadial& data) const {
  std::vector<double> out(data.coeffs);
  if (tilt_) out.insert(out.end(), data.tilt.begin(), data.tilt.end());
  return out;
}

NonRadialField::Local NonRadialField::LocalBasis(double s, double t) const {
  using Dual = ceres::Jet<double, 2>;
  const Dual sc = Clamp(Dual(s, 0), domain_[0], domain_[1]);
  const Dual tc = Clamp(Dual(t, 1), domain_[2], domain_[3]);
  const int span_s = FindSpan(knots_s_, kDegree, sc.a), span_t = FindSpan(knots_t_, kDegree, tc.a);
  Dual ns[kDegree + 1], mt[kDegree + 1];
  NonZeroBasis(knots_s_, kDegree, span_s, sc, ns);
  NonZeroBasis(knots_t_, kDegree, span_t, tc, mt);
  Local local;
  for (int b = 0, k = 0; b <= kDegree; ++b)
    for (int a = 0; a <= kDegree; ++a, ++k) {
      const Dual w = ns[a] * mt[b];
      local.index[k] = (span_t - kDegree + b) * cols_ + span_s - kDegree + a;
      local.weight[k] = w.a;
      local.by_s[k] = w.v[0];
      local.by_t[k] = w.v[1];
    }
  return local;
}

bool NonRadialField::Invert(const double* coeffs, const double m[2], double p[2]) const {
  double t[2] = {m[0], m[1]};
  auto untilt = [&] {
    if (!tilt_) {
      p[0] = t[0];
      p[1] = t[1];
      return true;
    }
    return UntiltPoint(coeffs + GridCoeffs(), t, p);
  };
  if (!grid()) return untilt();
  using Jet = ceres::Jet<double, 2>;
  for (int iteration = 0; iteration < 30; ++iteration) {
    Jet f[2];
    Evaluate(coeffs, Jet(t[0], 0), Jet(t[1], 1), f);
    const double e[2] = {t[0] + f[0].a - m[0], t[1] + f[1].a - m[1]};
    if (std::hypot(e[0], e[1]) <= 1e-12 * (1.0 + std::hypot(m[0], m[1]))) return untilt();
    const double J[4] = {1.0 + f[0].v[0], f[0].v[1], f[1].v[0], 1.0 + f[1].v[1]};
    const double det = J[0] * J[3] - J[1] * J[2];
    if (!(det > 0.0)) return false;
    t[0] -= (J[3] * e[0] - J[1] * e[1]) / det;
    t[1] -= (J[0] * e[1] - J[2] * e[0]) / det;
  }
  return false;
}

}  // namespace ws
