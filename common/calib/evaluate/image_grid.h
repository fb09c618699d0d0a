// A grid of points over an image, for maps of a camera's image (projection
// uncertainty, projection differences): cols x rows cells, point (i, j) at
// the centre of cell (i, j), row-major index j * cols + i; pixel (0, 0) is
// the centre of the top-left pixel.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <optional>

namespace ws::calib {

struct ImageGrid {
  int cols = 0, rows = 0;
  double step_x = 0, step_y = 0;  // pixels between grid points

  static ImageGrid Over(int width, int height, int cols, int rows) {
    return {cols, rows, double(width) / cols, double(height) / rows};
  }
  int size() const { return cols * rows; }
  Eigen::Vector2d Pixel(int i, int j) const {
    return {(i + 0.5) * step_x - 0.5, (j + 0.5) * step_y - 0.5};
  }
  // The index of the cell holding pixel q; nullopt outside the image.
  std::optional<int> Cell(const Eigen::Vector2d& q) const {
    const int i = int(std::floor((q.x() + 0.5) / step_x));
    const int j = int(std::floor((q.y() + 0.5) / step_y));
    if (i < 0 || i >= cols || j < 0 || j >= rows) return std::nullopt;
    return j * cols + i;
  }
};

}  // namespace ws::calib
