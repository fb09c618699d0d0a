#include "detect/saddle_point.h"

#include <cmath>
#include <opencv2/imgproc.hpp>

namespace ws {
namespace {

constexpr int kMaxIterations = 10;
constexpr double kConvergedPx = 1e-3;

}  // namespace

SaddleWindow::SaddleWindow(double sigma)
    : sigma_(sigma), h_(std::max(1, static_cast<int>(std::lround(2 * sigma)))), max_move_px_(std::max(1, h_)) {
  CV_Assert(sigma > 0);
  // The weighted least squares for (a, b, c, d, e, f) over whole-pixel
  // offsets x, y from the point: the same normal matrix at every step.
  Eigen::Matrix<double, 6, 6> normal = Eigen::Matrix<double, 6, 6>::Zero();
  for (int y = -h_; y <= h_; ++y)
    for (int x = -h_; x <= h_; ++x) {
      rows_.push_back((Vector6d() << x * x, x * y, y * y, x, y, 1).finished());
      weights_.push_back(std::exp(-double(x * x + y * y) / (h_ * h_)));
      normal.noalias() += weights_.back() * rows_.back() * rows_.back().transpose();
    }
  solver_.compute(normal);
  // d as a weighted sum of the smoothed window, its weights smoothed again:
  // d as a weighted sum of the image's own pixels, whose noise adds in
  // quadrature (by symmetry e's is the same).
  const int pad = static_cast<int>(std::ceil(4 * sigma)) + 1;
  cv::Mat kernel = cv::Mat::zeros(2 * (h_ + pad) + 1, 2 * (h_ + pad) + 1, CV_64F);
  for (size_t k = 0; k < rows_.size(); ++k) {
    Vector6d unit = Vector6d::Zero();
    unit(3) = 1;
    const double weight = weights_[k] * solver_.solve(unit).dot(rows_[k]);
    const int x = static_cast<int>(rows_[k](3)), y = static_cast<int>(rows_[k](4));
    kernel.at<double>(h_ + pad + y, h_ + pad + x) = weight;
  }
  cv::GaussianBlur(kernel, kernel, cv::Size(), sigma, sigma, cv::BORDER_CONSTANT);
  gradient_noise_gain_ = cv::norm(kernel);
}

std::optional<SaddleFit> SaddleWindow::Fit(const cv::Mat& gray, cv::Point2f start) const {
  // The smoothed patch, cut once: the window, one pixel for the bilinear
  // samples and max_move_px_ for the point's moves, and the Gaussian's
  // support (3 sigma) around them, so that the patch's border does not reach them.
  const int margin = h_ + 2 + static_cast<int>(std::ceil(max_move_px_ + 3 * sigma_));
  const cv::Point origin(static_cast<int>(std::lround(start.x)), static_cast<int>(std::lround(start.y)));
  const cv::Rect patch(origin.x - margin, origin.y - margin, 2 * margin + 1, 2 * margin + 1);
  if ((patch & cv::Rect(0, 0, gray.cols, gray.rows)) != patch) return std::nullopt;
  cv::Mat smooth;
  gray(patch).convertTo(smooth, CV_64F);
  cv::GaussianBlur(smooth, smooth, cv::Size(), sigma_);
  cv::Point2f p = start;
  std::vector<double> values(rows_.size());
  Vector6d q;
  Eigen::Matrix2d inverse;
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    // The smoothed image sampled (bilinearly) at those offsets from p
    // itself: a window centred on the corner is point-symmetric about it,
    // so the corner is where the iteration stops.
    const double ox = margin + p.x - origin.x, oy = margin + p.y - origin.y;
    const int ix = static_cast<int>(std::floor(ox)), iy = static_cast<int>(std::floor(oy));
    const double fx = ox - ix, fy = oy - iy;
    Vector6d rhs = Vector6d::Zero();
    size_t k = 0;
    for (int y = -h_; y <= h_; ++y) {
      const double* row0 = smooth.ptr<double>(iy + y);
      const double* row1 = smooth.ptr<double>(iy + y + 1);
      for (int x = -h_; x <= h_; ++x, ++k) {
        values[k] = (1 - fy) * ((1 - fx) * row0[ix + x] + fx * row0[ix + x + 1]) +
                    fy * ((1 - fx) * row1[ix + x] + fx * row1[ix + x + 1]);
        rhs += weights_[k] * values[k] * rows_[k];
      }
    }
    q = solver_.solve(rhs);
    Eigen::Matrix2d hessian;
    hessian << 2 * q(0), q(1), q(1), 2 * q(2);
    if (!(hessian.determinant() < 0)) return std::nullopt;  // no saddle here
    inverse = hessian.inverse();
    const Eigen::Vector2d s = -inverse * Eigen::Vector2d(q(3), q(4));
    const cv::Point2f next(static_cast<float>(p.x + s.x()), static_cast<float>(p.y + s.y()));
    if (!(cv::norm(next - start) <= max_move_px_)) return std::nullopt;
    p = next;
    if (s.norm() < kConvergedPx) break;
  }
  // How well the last quadratic fits the window it was fitted to.
  double total = 0, mean = 0;
  for (size_t k = 0; k < rows_.size(); ++k) {
    total += weights_[k];
    mean += weights_[k] * values[k];
  }
  mean /= total;
  double residual = 0, variance = 0;
  for (size_t k = 0; k < rows_.size(); ++k) {
    residual += weights_[k] * std::pow(values[k] - q.dot(rows_[k]), 2);
    variance += weights_[k] * std::pow(values[k] - mean, 2);
  }
  SaddleFit fit;
  fit.point = p;
  fit.error_per_noise = gradient_noise_gain_ * std::sqrt((inverse * inverse.transpose()).trace());
  fit.explained = variance > 0 ? 1 - residual / variance : 0;
  return fit;
}

}  // namespace ws
