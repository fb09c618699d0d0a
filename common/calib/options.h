// How a calibration is solved (calibrate.h): the model, the spline's knots
// and prior, robustness, what counts as enough data.
#pragma once

#include <functional>
#include <string>

namespace ws::calib {

// How the stereo rig is solved.
enum class StereoFlow {
  kPaper,  // each camera from its own views, then R, T (and the board poses) from the stereo pairs
  kJoint,  // the above as a start, then one solve of everything over all views
};

enum class RobustLoss { kNone, kHuber, kCauchy };

// The default number of estimated B-spline coefficients (--knots). With 13
// distinct knots (12 uniform spans over [0, r_max]) the least-squares spline
// follows the shipped Theia-like mustache curve within 0.004 px over the
// whole 1280 x 960 image (11 knots: 0.012 px, 9 knots: 0.03 px). That model
// error is small against 0.1 px of corner noise but not harmless: on the
// synthetic rig of the tests 11 knots bias fx by about 2 standard deviations,
// 13 knots by well under one. More knots only add variance where the corners
// are few (the periphery), and the smoothness prior keeps spans without
// corners tame.
inline constexpr int kDefaultKnots = 13;
// The default smoothness prior weight lambda (smoothness_prior.h).
inline constexpr double kDefaultSmoothness = 0.01;

struct CalibrationOptions {
  std::string model = "bspline";  // a registered kind: bspline, poly6, poly12
  // Distinct B-spline knots on [0, r_max]: knots - 1 uniform spans, knots + 2
  // basis functions of which `knots` are estimated (alpha_0 = alpha_1 = 0).
  int knots = kDefaultKnots;
  int degree = 3;
  // Smoothness prior weight lambda (smoothness_prior.h); 0 switches it off.
  double smoothness = kDefaultSmoothness;
  // r_max: the largest ideal radius the image reaches (its corners) times this.
  double r_max_margin = 1.03;

  RobustLoss robust_loss = RobustLoss::kNone;
  double robust_scale_px = 1.0;  // the loss's scale, pixels
  // Outlier rejection: after a solve, corners farther than
  // max(outlier_sigma * sigma, outlier_min_px) from their projection are
  // left out and the solve repeated while that changes (at most 5 rounds);
  // sigma is the robust (median-based) per-coordinate noise. 0 switches
  // rejection off.
  double outlier_sigma = 0;
  double outlier_min_px = 0.25;

  int min_views = 3;         // per camera
  int min_stereo_views = 3;  // views where both cameras see the board
  int min_points_per_view = 6;
  double min_view_angle_deg = 5.0;  // the board normals must spread at least this much
  StereoFlow flow = StereoFlow::kJoint;
  bool covariance = true;  // parameter standard deviations
  // Estimate the board's deflection (board_warp.h) with each camera's final
  // solve and the joint solve; otherwise the board is flat.
  bool board_warp = false;
  int max_iterations = 100;
  int grid_rows = 6, grid_cols = 8;  // the residual pattern per image region
  // Receives one line per stage (initialisation, each solve, r_max), for
  // logs; empty for none.
  std::function<void(const std::string&)> progress;
};

// Throws CalibrationError for options no calibration can use (unknown model,
// knots out of range, min_views below 3).
void CheckOptions(const CalibrationOptions& options);

}  // namespace ws::calib
