#include "detect/saddle_point.h"

#include <Eigen/Dense>
#include <cmath>
#include <vector>
#include <opencv2/imgproc.hpp>

namespace ws {

cv::Point2f SaddlePoint(const cv::Mat& gray, cv::Point2f start, double sigma) {
  constexpr int kMaxIterations = 10;
  constexpr double kMaxMovePx = 1.0, kConvergedPx = 1e-3;
  const int h = std::max(1, static_cast<int>(std::lround(2 * sigma)));
  // The smoothed patch, cut once: the window, one pixel for the bilinear
  // samples and kMaxMovePx for the point's moves, and the Gaussian's support
  // (3 sigma) around them, so that the patch's border does not reach them.
  const int margin = h + 2 + static_cast<int>(std::ceil(kMaxMovePx + 3 * sigma));
  const cv::Point origin(static_cast<int>(std::lround(start.x)), static_cast<int>(std::lround(start.y)));
  const cv::Rect patch(origin.x - margin, origin.y - margin, 2 * margin + 1, 2 * margin + 1);
  if ((patch & cv::Rect(0, 0, gray.cols, gray.rows)) != patch) return start;
  cv::Mat smooth;
  gray(patch).convertTo(smooth, CV_64F);
  cv::GaussianBlur(smooth, smooth, cv::Size(), sigma);
  // The weighted least squares for (a, b, c, d, e, f) over whole-pixel
  // offsets x, y from the point: the same normal matrix at every step.
  using Vector6d = Eigen::Matrix<double, 6, 1>;
  std::vector<Vector6d> rows;
  std::vector<double> weights;
  Eigen::Matrix<double, 6, 6> normal = Eigen::Matrix<double, 6, 6>::Zero();
  for (int y = -h; y <= h; ++y)
    for (int x = -h; x <= h; ++x) {
      rows.push_back((Vector6d() << x * x, x * y, y * y, x, y, 1).finished());
      weights.push_back(std::exp(-double(x * x + y * y) / (h * h)));
      normal.noalias() += weights.back() * rows.back() * rows.back().transpose();
    }
  const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> solver(normal);
  cv::Point2f p = start;
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    // The smoothed image sampled (bilinearly) at those offsets from p
    // itself: a window centred on the corner is point-symmetric about it,
    // so the corner is where the iteration stops.
    const double ox = margin + p.x - origin.x, oy = margin + p.y - origin.y;
    const int ix = static_cast<int>(std::floor(ox)), iy = static_cast<int>(std::floor(oy));
    const double fx = ox - ix, fy = oy - iy;
    Vector6d rhs = Vector6d::Zero();
    size_t k = 0;
    for (int y = -h; y <= h; ++y) {
      const double* row0 = smooth.ptr<double>(iy + y);
      const double* row1 = smooth.ptr<double>(iy + y + 1);
      for (int x = -h; x <= h; ++x, ++k) {
        const double value = (1 - fy) * ((1 - fx) * row0[ix + x] + fx * row0[ix + x + 1]) +
                             fy * ((1 - fx) * row1[ix + x] + fx * row1[ix + x + 1]);
        rhs += weights[k] * value * rows[k];
      }
    }
    const Vector6d q = solver.solve(rhs);
    Eigen::Matrix2d hessian;
    hessian << 2 * q(0), q(1), q(1), 2 * q(2);
    if (!(hessian.determinant() < 0)) return start;  // no saddle here
    const Eigen::Vector2d s = -hessian.inverse() * Eigen::Vector2d(q(3), q(4));
    const cv::Point2f next(static_cast<float>(p.x + s.x()), static_cast<float>(p.y + s.y()));
    if (!(cv::norm(next - start) <= kMaxMovePx)) return start;
    p = next;
    if (s.norm() < kConvergedPx) return p;
  }
  return p;
}

}  // namespace ws
