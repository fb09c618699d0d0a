#include "detect/saddle_point.h"

#include <Eigen/Dense>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace ws {

cv::Point2f SaddlePoint(const cv::Mat& gray, cv::Point2f start, double sigma) {
  constexpr int kMaxIterations = 10;
  constexpr double kMaxMovePx = 1.0, kConvergedPx = 1e-3;
  const int h = std::max(1, static_cast<int>(std::lround(2 * sigma)));
  // The window, the Gaussian's support (3 sigma) around it, and the pixel
  // the point may move before the patch is cut again.
  const int margin = h + static_cast<int>(std::ceil(3 * sigma)) + 2;
  const cv::Rect image(0, 0, gray.cols, gray.rows);
  cv::Point2f p = start;
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    const cv::Point centre(static_cast<int>(std::lround(p.x)), static_cast<int>(std::lround(p.y)));
    const cv::Rect patch(centre.x - margin, centre.y - margin, 2 * margin + 1, 2 * margin + 1);
    if ((patch & image) != patch) return start;
    cv::Mat smooth;
    gray(patch).convertTo(smooth, CV_64F);
    cv::GaussianBlur(smooth, smooth, cv::Size(), sigma);
    // Weighted least squares for (a, b, c, d, e, f) on the smoothed image
    // sampled (bilinearly) at whole-pixel offsets x, y from p itself: a
    // window centred on the corner is point-symmetric about it, so the
    // corner is where the iteration stops.
    const double ox = margin + p.x - centre.x, oy = margin + p.y - centre.y;
    const int ix = static_cast<int>(std::floor(ox)), iy = static_cast<int>(std::floor(oy));
    const double fx = ox - ix, fy = oy - iy;
    Eigen::Matrix<double, 6, 6> normal = Eigen::Matrix<double, 6, 6>::Zero();
    Eigen::Matrix<double, 6, 1> rhs = Eigen::Matrix<double, 6, 1>::Zero();
    for (int y = -h; y <= h; ++y)
      for (int x = -h; x <= h; ++x) {
        const double* row0 = smooth.ptr<double>(iy + y);
        const double* row1 = smooth.ptr<double>(iy + y + 1);
        const double value = (1 - fy) * ((1 - fx) * row0[ix + x] + fx * row0[ix + x + 1]) +
                             fy * ((1 - fx) * row1[ix + x] + fx * row1[ix + x + 1]);
        const double w = std::exp(-double(x * x + y * y) / (h * h));
        Eigen::Matrix<double, 6, 1> row;
        row << x * x, x * y, y * y, x, y, 1;
        normal.noalias() += w * row * row.transpose();
        rhs += w * value * row;
      }
    const Eigen::Matrix<double, 6, 1> q = normal.ldlt().solve(rhs);
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
