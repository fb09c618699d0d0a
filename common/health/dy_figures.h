// The figures of a set of matches: vertical disparity dy = v_right - v_left
// in rectified pixels, its median and 95th percentile in absolute value, and
// the median dy (signed) per region of the left rectified image. A pitch
// error between the cameras shifts every row alike (dy of one sign, larger
// towards the top and bottom of a wide field), a roll turns them (dy growing
// with x), a yaw bends them (dy growing with x y).
#pragma once

#include <vector>

#include <opencv2/core.hpp>

namespace ws {

struct DyMatch {
  cv::Point2f left;  // rectified pixel of the left image
  float dy;          // v_right - v_left, rectified pixels
};

struct DyGrid {
  int rows = 3, cols = 4;
};

struct DyFigures {
  int matches = 0;
  double median_abs = -1, p95_abs = -1;  // px; -1 without matches
  std::vector<std::vector<double>> region_dy;   // [row][col] median dy, 0 where empty
  std::vector<std::vector<int>> region_matches;  // [row][col]
  int regions_with(int min_matches) const;
};

// The q-quantile (0..1) of `values` by nearest rank; -1 when empty.
double Quantile(std::vector<double> values, double q);

// Figures of `matches` over a grid on an image of `size`.
DyFigures ComputeDyFigures(const std::vector<DyMatch>& matches, cv::Size size, const DyGrid& grid);

}  // namespace ws
