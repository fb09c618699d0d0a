#include "models/monotone_cubic.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace ws {
namespace {

// The end slope from the one-sided three-point formula, limited so that the
// end interval stays monotone (h0, d0: the end interval; h1, d1: the next).
double EndSlope(double h0, double h1, double d0, double d1) {
  const double slope = ((2 * h0 + h1) * d0 - h0 * d1) / (h0 + h1);
  if (slope * d0 <= 0) return 0;
  if (d0 * d1 <= 0 && std::abs(slope) > 3 * std::abs(d0)) return 3 * d0;
  return slope;
}

}  // namespace

MonotoneCubic::MonotoneCubic(std::vector<double> x, std::vector<double> y)
    : x_(std::move(x)), y_(std::move(y)) {
  const size_t n = x_.size();
  if (n < 2 || y_.size() != n)
    throw std::invalid_argument("monotone cubic needs at least 2 points and as many x as y");
  std::vector<double> h(n - 1), d(n - 1);  // interval widths and secant slopes
  for (size_t i = 0; i + 1 < n; ++i) {
    h[i] = x_[i + 1] - x_[i];
    if (!(h[i] > 0)) throw std::invalid_argument("monotone cubic needs strictly increasing x");
    d[i] = (y_[i + 1] - y_[i]) / h[i];
  }
  slope_.assign(n, d[0]);
  if (n == 2) return;
  for (size_t i = 1; i + 1 < n; ++i) {
    if (d[i - 1] * d[i] <= 0) {
      slope_[i] = 0;  // a local extremum of the data stays one
    } else {  // weighted harmonic mean of the neighbouring secants
      const double w1 = 2 * h[i] + h[i - 1], w2 = h[i] + 2 * h[i - 1];
      slope_[i] = (w1 + w2) / (w1 / d[i - 1] + w2 / d[i]);
    }
  }
  slope_[0] = EndSlope(h[0], h[1], d[0], d[1]);
  slope_[n - 1] = EndSlope(h[n - 2], h[n - 3], d[n - 2], d[n - 3]);
}

double MonotoneCubic::operator()(double t) const {
  const auto above = std::upper_bound(x_.begin() + 1, x_.end() - 1, t);
  const size_t i = static_cast<size_t>(above - x_.begin()) - 1;
  const double h = x_[i + 1] - x_[i];
  const double s = (t - x_[i]) / h;
  // Cubic Hermite basis on [x_i, x_{i+1}].
  const double h00 = (1 + 2 * s) * (1 - s) * (1 - s), h10 = s * (1 - s) * (1 - s);
  const double h01 = s * s * (3 - 2 * s), h11 = s * s * (s - 1);
  return h00 * y_[i] + h10 * h * slope_[i] + h01 * y_[i + 1] + h11 * h * slope_[i + 1];
}

}  // namespace ws
