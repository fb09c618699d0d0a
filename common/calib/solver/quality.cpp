#include "calib/solver/quality.h"

#include <algorithm>
#include <cmath>

namespace ws::calib {

double Rms(const std::vector<CornerResidual>& residuals) {
  double sum = 0;
  int n = 0;
  for (const auto& r : residuals) {
    if (r.outlier) continue;
    sum += r.residual.squaredNorm();
    ++n;
  }
  return n ? std::sqrt(sum / n) : 0.0;
}

std::vector<double> ViewRms(const std::vector<CornerResidual>& residuals, int num_views) {
  std::vector<double> sum(num_views, 0.0);
  std::vector<int> n(num_views, 0);
  for (const auto& r : residuals) {
    if (r.outlier || r.view < 0 || r.view >= num_views) continue;
    sum[r.view] += r.residual.squaredNorm();
    ++n[r.view];
  }
  std::vector<double> rms(num_views, -1.0);
  for (int v = 0; v < num_views; ++v)
    if (n[v]) rms[v] = std::sqrt(sum[v] / n[v]);
  return rms;
}

int ResidualGrid::Cell(double u, double v) const {
  if (rows <= 0 || cols <= 0 || image_width <= 0 || image_height <= 0) return -1;
  // Pixel centres are integers: the image spans [-0.5, size - 0.5).
  const int c = static_cast<int>(std::floor((u + 0.5) * cols / image_width));
  const int r = static_cast<int>(std::floor((v + 0.5) * rows / image_height));
  if (c < 0 || c >= cols || r < 0 || r >= rows) return -1;
  return r * cols + c;
}

Eigen::Vector2d ResidualGrid::CellCentre(int cell) const {
  const int r = cell / cols, c = cell % cols;
  return {(c + 0.5) * image_width / cols - 0.5, (r + 0.5) * image_height / rows - 0.5};
}

ResidualGrid MakeResidualGrid(const std::vector<CornerResidual>& residuals, int image_width,
                              int image_height, int rows, int cols) {
  ResidualGrid grid;
  grid.rows = rows;
  grid.cols = cols;
  grid.image_width = image_width;
  grid.image_height = image_height;
  const int cells = std::max(0, rows * cols);
  grid.count.assign(cells, 0);
  grid.mean.assign(cells, Eigen::Vector2d::Zero());
  grid.rms.assign(cells, 0.0);
  for (const auto& r : residuals) {
    if (r.outlier) continue;
    const int cell = grid.Cell(r.observed.x(), r.observed.y());
    if (cell < 0) continue;
    ++grid.count[cell];
    grid.mean[cell] += r.residual;
    grid.rms[cell] += r.residual.squaredNorm();
  }
  for (int cell = 0; cell < cells; ++cell)
    if (grid.count[cell]) {
      grid.mean[cell] /= grid.count[cell];
      grid.rms[cell] = std::sqrt(grid.rms[cell] / grid.count[cell]);
    }
  return grid;
}

double Median(std::vector<double> values) {
  if (values.empty()) return -1;
  const size_t mid = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + mid, values.end());
  return values[mid];
}

double RobustSigma(const std::vector<CornerResidual>& residuals) {
  std::vector<double> norms;
  for (const auto& r : residuals)
    if (!r.outlier) norms.push_back(r.residual.norm());
  if (norms.empty()) return 0;
  return Median(std::move(norms)) / std::sqrt(2.0 * std::log(2.0));
}

double RmsSigma(const std::vector<CornerResidual>& residuals) {
  double sum = 0;
  int n = 0;
  for (const auto& r : residuals)
    if (!r.outlier) sum += r.residual.squaredNorm(), ++n;
  return n ? std::sqrt(sum / (2.0 * n)) : 0.0;
}

int MarkOutliers(std::vector<CornerResidual>& residuals, double threshold) {
  int changed = 0;
  for (auto& r : residuals) {
    const bool outlier = !(r.residual.norm() <= threshold);
    changed += outlier != r.outlier;
    r.outlier = outlier;
  }
  return changed;
}

}  // namespace ws::calib
