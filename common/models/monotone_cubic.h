// Monotone piecewise-cubic Hermite interpolation (Fritsch & Carlson 1980,
// with the Fritsch-Butland slopes of PCHIP): through every point, C^1, and
// monotone wherever the data are, so it never overshoots a monotone table.
// It is the reference curve between the rows of a lens table.
#pragma once

#include <vector>

namespace ws {

class MonotoneCubic {
 public:
  // x strictly increasing, at least 2 points; throws std::invalid_argument.
  MonotoneCubic(std::vector<double> x, std::vector<double> y);

  // The interpolant at t; outside [x_0, x_{N-1}] the end cubics continue.
  double operator()(double t) const;

 private:
  std::vector<double> x_, y_, slope_;
};

}  // namespace ws
