// B-spline basis functions and knot vectors (paper Eqs. 3-5 and 8).
//
// A knot vector t_0 <= t_1 <= ... <= t_{n+K} of degree K defines n basis
// functions N_{i,K}, i = 0..n-1, by the de Boor-Cox recursion
//
//   N_{i,0}(r) = 1 if t_i <= r < t_{i+1}, 0 otherwise                   (Eq. 4)
//   N_{i,K}(r) = (r - t_i) / (t_{i+K} - t_i) N_{i,K-1}(r)
//              + (t_{i+K+1} - r) / (t_{i+K+1} - t_{i+1}) N_{i+1,K-1}(r)    (Eq. 5)
//
// with 0/0 read as 0, and a spline B(r) = sum_i alpha_i N_{i,K}(r) (Eq. 3).
// The spline's domain is [t_K, t_n]; on a span [t_l, t_{l+1}) only the K+1
// functions N_{l-K..l,K} are non-zero, non-negative and sum to one.
//
// Clamped knots repeat each end knot K+1 times (t_0 = ... = t_K = a,
// t_n = ... = t_{n+K} = b), so that B(a) = alpha_0, B(b) = alpha_{n-1} and
// B'(a) = K (alpha_1 - alpha_0) / (t_{K+1} - a).
//
// Outside the domain (r < t_K, r >= t_n) every function here continues the
// polynomial piece of the first, respectively last, non-empty span: a spline
// has a value for every r, and it is C^infinity beyond the end knots.
#pragma once

#include <vector>

namespace ws {

// Degrees above this are rejected (they are never useful for lens curves, and
// the bound lets the basis be evaluated without allocating).
constexpr int kMaxSplineDegree = 10;
// At most this many knots: far more than any lens needs (--knots auto tries
// up to 31), few enough that a file or message cannot make a model costly.
constexpr int kMaxKnots = 512;

// n = knots.size() - degree - 1.
int NumBasisFunctions(const std::vector<double>& knots, int degree);

// Throws std::invalid_argument unless 1 <= degree <= kMaxSplineDegree, the
// knots are finite and non-decreasing, there are at least 2 (degree + 1) of
// them and at most kMaxKnots, and the domain [t_K, t_n] is not empty.
void ValidateKnots(const std::vector<double>& knots, int degree);

// The span l (degree <= l <= n - 1, t_l < t_{l+1}) whose polynomial piece
// gives the spline at r: t_l <= r < t_{l+1} inside the domain, the first or
// last non-empty span outside it.
int FindSpan(const std::vector<double>& knots, int degree, double r);

// values[j] = N_{span-degree+j, degree}(r) for j = 0..degree: the de Boor-Cox
// recursion (Eq. 5) run upwards from N_{span,0} = 1 over the functions that
// are non-zero on the span (Piegl & Tiller, The NURBS Book, A2.2). Templated
// so that r may be a ceres::Jet; the knots are fixed data.
template <typename T>
void NonZeroBasis(const std::vector<double>& knots, int degree, int span, const T& r, T* values) {
  T left[kMaxSplineDegree + 1];
  T right[kMaxSplineDegree + 1];
  values[0] = T(1.0);
  for (int j = 1; j <= degree; ++j) {
    left[j] = r - knots[span + 1 - j];
    right[j] = knots[span + j] - r;
    T saved(0.0);
    for (int k = 0; k < j; ++k) {
      // t_{span+k+1} - t_{span+k+1-j} > 0 because the span is not empty.
      const T term = values[k] / (knots[span + k + 1] - knots[span + k + 1 - j]);
      values[k] = saved + right[k + 1] * term;
      saved = left[j - k] * term;
    }
    values[j] = saved;
  }
}

// NonZeroBasis at r, with each value's derivative d/dr in slopes[j]: the
// recursion run on the dual number r + dr.
void NonZeroBasisWithSlopes(const std::vector<double>& knots, int degree, int span, double r,
                            double* values, double* slopes);

// All n basis values at r (zero outside their support): one row of the
// collocation matrix A of Eq. 9.
std::vector<double> EvaluateBasis(const std::vector<double>& knots, int degree, double r);

// Clamped knots for interpolating at the strictly increasing sites r_0..r_{N-1}
// (paper Eq. 8, de Boor's averaging): t_0 = ... = t_K = r_0,
// t_{j+K} = (r_j + ... + r_{j+K-1}) / K for j = 1..N-K-1,
// t_N = ... = t_{N+K} = r_{N-1}. They satisfy the Schoenberg-Whitney conditions
// t_i < r_i < t_{i+K+1} (ends excepted), so the N x N collocation matrix is
// invertible. Needs N >= degree + 1.
std::vector<double> SchoenbergWhitneyKnots(const std::vector<double>& sites, int degree);

// Clamped knots on [0, r_max] with `intervals` equal spans: n = intervals +
// degree basis functions.
std::vector<double> UniformClampedKnots(double r_max, int intervals, int degree);

}  // namespace ws
