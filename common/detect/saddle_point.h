// A chessboard corner refined as the saddle point of the smoothed image
// (Lucchese & Mitra, "Using saddle points for subpixel feature detection in
// camera calibration targets", APCCAS 2002; ROCHADE, Placht et al., ECCV
// 2014, refines the same way).
//
// Smoothed by a Gaussian of scale sigma, the image around an X-junction of
// two edges is a saddle. A quadratic
//
//   I(x, y) = a x^2 + b x y + c y^2 + d x + e y + f
//
// fitted by least squares over a window of half-width h = round(2 sigma)
// (weights exp(-(x^2 + y^2) / h^2)) has its stationary point, the solution
// of [2a b; b 2c] s = -[d; e], at the corner; the fit is repeated about the
// point itself (the window sampled bilinearly) until it moves less than
// 1e-3 px. Two straight edges crossing make an image point-symmetric about
// the corner, and so is its smoothed image: the saddle is the corner at
// every scale. Curved edges (a wide lens, a board in perspective) and
// uneven light break the symmetry more the larger the window, while the
// image noise moves the saddle less: corner_refinement.h chooses the scale.
//
// The fit also says how far to trust it:
// - its standard error: the image noise (grey levels, independent per
//   pixel) propagated through the smoothing and the least squares to
//   (d, e), then through the Hessian to the point;
// - the share of the smoothed window's variance the quadratic explains. An
//   ideal X-junction, sharp or blurred, its edges crossing at 90 degrees
//   down to 20, gives 0.85 to 0.99 (tests/detect/test_saddle_point.cpp); a
//   window holding something else (a marker, a highlight, the board's
//   border) much less.
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Dense>
#include <opencv2/core.hpp>

namespace ws {

struct SaddleFit {
  cv::Point2f point;
  // The standard error of the point (pixels, the two coordinates together)
  // for image noise of one grey level: multiply by the image's noise.
  double error_per_noise = 0;
  double explained = 0;  // share of the window's variance the quadratic explains, <= 1
};

// The fit at one scale: the window and its least squares, the same for
// every corner, so made once.
class SaddleWindow {
 public:
  // sigma in pixels, > 0.
  explicit SaddleWindow(double sigma);

  // The saddle point near `start` (within the window's half-width of it, at
  // least 1 px) in an 8-bit single-channel image; nothing when there is none
  // there: the fit is no saddle (its Hessian is not indefinite), the window
  // leaves the image, or the point wanders farther.
  std::optional<SaddleFit> Fit(const cv::Mat& gray, cv::Point2f start) const;

  double sigma() const { return sigma_; }

 private:
  using Vector6d = Eigen::Matrix<double, 6, 1>;
  double sigma_;
  int h_;
  double max_move_px_;
  std::vector<Vector6d> rows_;
  std::vector<double> weights_;
  Eigen::LDLT<Eigen::Matrix<double, 6, 6>> solver_;
  double gradient_noise_gain_;  // standard deviation of d (and e) per grey level of image noise
};

}  // namespace ws
