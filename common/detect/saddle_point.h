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
// nearest pixel to that point until it moves less than 1e-3 px.
//
// cv::cornerSubPix, the usual refinement, locks towards pixel positions on
// sharp rendered boards (0.05 px RMS on config/sim/sharp-knee.yaml's
// rendered views whatever the noise; tests/detect/test_detector_accuracy.cpp
// measures both); the saddle of the smoothed image averages that away.
#pragma once

#include <opencv2/core.hpp>

namespace ws {

// The saddle point near `start` (within 1 px of it) at scale sigma (pixels,
// > 0) in an 8-bit single-channel image; `start` itself when there is none
// there: the fit is no saddle (its Hessian is not indefinite), the window
// leaves the image, or the point wanders more than 1 px.
cv::Point2f SaddlePoint(const cv::Mat& gray, cv::Point2f start, double sigma);

}  // namespace ws
