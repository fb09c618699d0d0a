#include "health/dy_figures.h"

#include <algorithm>
#include <cmath>

namespace ws {

int DyFigures::regions_with(int min_matches) const {
  int n = 0;
  for (const auto& row : region_matches)
    for (int count : row) n += count >= min_matches;
  return n;
}

double Quantile(std::vector<double> values, double q) {
  if (values.empty()) return -1;
  const size_t k = std::min(values.size() - 1, size_t(std::ceil(q * double(values.size()))) - (q > 0));
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(k), values.end());
  return values[k];
}

DyFigures ComputeDyFigures(const std::vector<DyMatch>& matches, cv::Size size, const DyGrid& grid) {
  DyFigures f;
  f.matches = int(matches.size());
  std::vector<std::vector<std::vector<double>>> cells(size_t(grid.rows),
                                                      std::vector<std::vector<double>>(size_t(grid.cols)));
  std::vector<double> abs_dy;
  abs_dy.reserve(matches.size());
  for (const DyMatch& m : matches) {
    abs_dy.push_back(std::abs(m.dy));
    const int r = std::clamp(int(m.left.y * grid.rows / size.height), 0, grid.rows - 1);
    const int c = std::clamp(int(m.left.x * grid.cols / size.width), 0, grid.cols - 1);
    cells[size_t(r)][size_t(c)].push_back(m.dy);
  }
  f.median_abs = Quantile(abs_dy, 0.5);
  f.p95_abs = Quantile(abs_dy, 0.95);
  for (const auto& row : cells) {
    f.region_dy.emplace_back();
    f.region_matches.emplace_back();
    for (const auto& cell : row) {
      f.region_dy.back().push_back(cell.empty() ? 0 : Quantile(cell, 0.5));
      f.region_matches.back().push_back(int(cell.size()));
    }
  }
  return f;
}

}  // namespace ws
