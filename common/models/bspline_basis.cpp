#include "models/bspline_basis.h"

#include <algorithm>
#include <ceres/jet.h>
#include <cmath>
#include <stdexcept>
#include <string>

namespace ws {

int NumBasisFunctions(const std::vector<double>& knots, int degree) {
  return static_cast<int>(knots.size()) - degree - 1;
}

void ValidateKnots(const std::vector<double>& knots, int degree) {
  if (degree < 1 || degree > kMaxSplineDegree)
    throw std::invalid_argument("B-spline degree must be in 1.." + std::to_string(kMaxSplineDegree) +
                                ", not " + std::to_string(degree));
  if (knots.size() < 2 * static_cast<size_t>(degree + 1))
    throw std::invalid_argument("a degree-" + std::to_string(degree) + " B-spline needs at least " +
                                std::to_string(2 * (degree + 1)) + " knots, got " +
                                std::to_string(knots.size()));
  if (knots.size() > size_t(kMaxKnots))
    throw std::invalid_argument("at most " + std::to_string(kMaxKnots) + " knots, got " +
                                std::to_string(knots.size()));
  for (size_t i = 0; i < knots.size(); ++i) {
    if (!std::isfinite(knots[i]))
      throw std::invalid_argument("knot " + std::to_string(i) + " is not finite");
    if (i > 0 && knots[i] < knots[i - 1])
      throw std::invalid_argument("knots must not decrease: t_" + std::to_string(i) + " = " +
                                  std::to_string(knots[i]) + " < t_" + std::to_string(i - 1) +
                                  " = " + std::to_string(knots[i - 1]));
  }
  if (!(knots[degree] < knots[NumBasisFunctions(knots, degree)]))
    throw std::invalid_argument("the B-spline domain [t_K, t_n] is empty");
}

int FindSpan(const std::vector<double>& knots, int degree, double r) {
  const int n = NumBasisFunctions(knots, degree);
  auto empty = [&](int span) { return !(knots[span] < knots[span + 1]); };
  if (r < knots[degree]) {  // before the domain: first non-empty span
    int span = degree;
    while (empty(span)) ++span;
    return span;
  }
  // The first of t_{K+1}..t_{n-1} above r ends the span (t_n if none does).
  const auto end = std::upper_bound(knots.begin() + degree + 1, knots.begin() + n, r);
  int span = static_cast<int>(end - knots.begin()) - 1;
  while (empty(span)) --span;  // at or past t_n: last non-empty span
  return span;
}

void NonZeroBasisWithSlopes(const std::vector<double>& knots, int degree, int span, double r,
                            double* values, double* slopes) {
  using Dual = ceres::Jet<double, 1>;
  Dual basis[kMaxSplineDegree + 1];
  NonZeroBasis(knots, degree, span, Dual(r, 0), basis);
  for (int j = 0; j <= degree; ++j) {
    values[j] = basis[j].a;
    slopes[j] = basis[j].v[0];
  }
}

std::vector<double> EvaluateBasis(const std::vector<double>& knots, int degree, double r) {
  std::vector<double> basis(NumBasisFunctions(knots, degree), 0.0);
  const int span = FindSpan(knots, degree, r);
  NonZeroBasis(knots, degree, span, r, &basis[span - degree]);
  return basis;
}

std::vector<double> SchoenbergWhitneyKnots(const std::vector<double>& sites, int degree) {
  const int n = static_cast<int>(sites.size());
  if (degree < 1 || n < degree + 1)
    throw std::invalid_argument("interpolation by a degree-" + std::to_string(degree) +
                                " spline needs at least " + std::to_string(degree + 1) +
                                " sites, got " + std::to_string(n));
  for (int i = 1; i < n; ++i)
    if (!(sites[i] > sites[i - 1]))
      throw std::invalid_argument("interpolation sites must increase strictly");
  std::vector<double> knots(degree + 1, sites.front());
  for (int j = 1; j <= n - degree - 1; ++j) {
    double sum = 0.0;
    for (int i = j; i < j + degree; ++i) sum += sites[i];
    knots.push_back(sum / degree);
  }
  knots.insert(knots.end(), degree + 1, sites.back());
  return knots;
}

std::vector<double> UniformClampedKnots(double r_max, int intervals, int degree) {
  if (!(r_max > 0) || !std::isfinite(r_max))
    throw std::invalid_argument("uniform knots need a positive r_max, not " + std::to_string(r_max));
  if (intervals < 1)
    throw std::invalid_argument("uniform knots need at least one interval");
  std::vector<double> knots(degree + 1, 0.0);
  for (int i = 1; i < intervals; ++i) knots.push_back(r_max * i / intervals);
  knots.insert(knots.end(), degree + 1, r_max);
  return knots;
}

}  // namespace ws
