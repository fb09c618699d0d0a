// How a calibration is solved (calibrate.h): the model, the spline's knots
// and prior, robustness, what counts as enough data.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "models/model_kind.h"

namespace ws::calib {

// How the stereo rig is solved.
enum class StereoFlow {
  kPaper,  // each camera from its own views, then R, T (and the board poses) from the stereo pairs
  kJoint,  // the above as a start, then one solve of everything over all views
};

enum class RobustLoss { kNone, kHuber, kCauchy };

// Which corners are outliers after a solve (outliers.h): those farther from
// their projection than a threshold of the camera's robust noise level
// sigma (RobustSigma, quality.h: from the median corner error).
enum class OutlierRule {
  kOff,        // every corner kept
  // The default, Chauvenet's criterion with an alarm, as mrcal iterates its
  // own (mrcal.c markOutliers: 4 sigma, once a corner is past 5 sigma).
  // sigma is the per-coordinate RMS of the inliers' residuals, or the
  // views' detection noise where that is larger (corner_noise.h: a model
  // that fits better than its corners are detected leaves out no corner for
  // missing by less than the detection's own noise). A solve is
  // contaminated when a corner lies beyond the alarm level, which N corners
  // of Gaussian noise pass with 1 % probability,
  //   t_alarm = sigma sqrt(2 ln 100N)   (N P(|e| > t) = 0.01,
  //                                      P(|e| > t) = exp(-t^2 / 2 sigma^2));
  // then every corner beyond Chauvenet's level, which the noise passes
  // half a corner's worth, t = sigma sqrt(2 ln 2N), is left out and the
  // camera solved again, until no corner is past the alarm. N the camera's
  // corners: 4.1 and 5.0 sigma for 2000 corners. A corner detected wrongly
  // (blurred, half-occluded, a reflection) lies far beyond them; the noise
  // of good corners does not.
  kChauvenet,
  kSigma,      // beyond outlier_sigma * sigma (--outlier-sigma K)
};

// Whether the board's bow (board_warp.h) is estimated.
enum class WarpRule {
  kFlat,       // the board held flat
  // The default: each camera's final solve is repeated with the bow free,
  // and the bow kept where the rule of selection.h prefers it to the flat
  // board (the simpler candidate); reported with its standard deviation
  // either way.
  kAuto,
  kEstimated,  // always estimated
};

// --knots auto (SplineOptions::knots empty, the default): the
// number of estimated B-spline coefficients is chosen per camera from the
// data, by K-fold cross-validation (heldout.h): the counts of kKnotLadder are
// tried in turn, each solved from the last solution's curve, until two in a
// row are no better than the best so far; the count the rule of
// selection.h keeps is solved (more coefficients only where they predict
// better beyond the folds' spread). A lens with a
// sharp knee needs more coefficients than a gentle one; the held-out error, not the fitted one, shows where more
// stop paying (they only add variance where corners are few).
// The counts tried, about 25 % apart, each from the curve of one solve with
// kContinuationKnots: the radial continuation (mono_solve.h) needs a curve
// that can follow the lens while its discs grow, or a knee it cannot follow
// pulls fx and the poses into a false minimum no later count leaves (13
// coefficients do so on config/sim/sharp-knee.yaml); the smoothness prior
// holds the spans no corner reaches yet. It is only the start: the data
// choose after it.
inline constexpr int kKnotLadder[] = {7, 9, 11, 13, 16, 20, 25, 31, 39, 48, 60};
// The ladder stops only where more coefficients stop paying in the fit
// too: a count that fits more than this factor worse than a smaller count
// did not reach its own optimum (a richer curve fits at least as well, up
// to where its knots sit), so it is no sign that the counts above it fail.
// On config/sim/sharp-knee.yaml bspline_theta's 9 and 11 fit 0.17 and 0.15
// px where 7 fit 0.12 px and 25 fit 0.05 px.
inline constexpr double kMissedFit = 1.05;
inline constexpr int kContinuationKnots = 25;
// The default smoothness prior weight lambda (smoothness_prior.h).
inline constexpr double kDefaultSmoothness = 0.01;

// The non-radial part of the lens model (models/nonradial_field.h): a
// sensor tilt (models/sensor_tilt.h) and a field.
enum class FieldRule {
  kNone,  // radial only
  // The default: per camera, after the radial model, its knots and the
  // board's bow are settled, by the rule of selection.h: first the sensor
  // tilt against none, solved and cross-validated on the same corners.
  // Then, where the held-out RMS exceeds the corners' own noise by more
  // than it resolves, on top of what that kept, fields are solved and
  // cross-validated in two ladders: the finest grid of kFieldLadder (rows
  // in proportion to the image) at each weight of kFieldSmoothnessLadder,
  // smooth to rough; then the coarser grids at the weight that predicted
  // best (a coarse one may miss what a finer one finds); each until two in
  // a row predict worse than its best beyond the spread (over-fitting).
  // The field of the lowest held-out RMS (its grid and smoothness tuned by
  // cross-validation) is then weighed against none. A radially symmetric
  // lens comes out as none. With several models, the non-radial
  // part is chosen for the model the radial comparison chose (calibrate.h).
  kAuto,
  kGrid,  // given: field_tilt, and field_cols x field_rows control points (0 x 0: no field)
};
inline constexpr int kFieldLadder[] = {4, 6, 8, 11, 16};
// The field's smoothness weights lambda (nonradial_prior.h) tried, smooth
// to rough, half a decade apart: how much bending the views support is
// their held-out error's to say (a rich grid with its roughness chosen by
// cross-validation: Eilers and Marx, "Flexible smoothing with B-splines and
// penalties", Statistical Science 1996).
inline constexpr double kFieldSmoothnessLadder[] = {10, 3.16, 1, 0.316, 0.1, 0.0316, 0.01};

// The B-spline's settings (the spline models; camera_block.h): its knots,
// degree and smoothness prior.
struct SplineOptions {
  // Distinct B-spline knots on [0, r_max]: knots - 1 uniform spans, knots + 2
  // basis functions of which `knots` are estimated (alpha_0 = alpha_1 = 0);
  // empty: --knots auto, chosen by cross-validation (above). The solver
  // takes a count: auto is settled before (mono_solve.h).
  std::optional<int> knots;
  int degree = 3;
  // Smoothness prior weight lambda (smoothness_prior.h); 0 switches it off.
  double smoothness = kDefaultSmoothness;
};

struct CalibrationOptions {
  ModelKind model = ModelKind::kBspline;
  SplineOptions spline;
  // r_max: the largest ideal radius the image reaches (its corners) times this.
  double r_max_margin = 1.03;

  RobustLoss robust_loss = RobustLoss::kNone;
  double robust_scale_px = 1.0;  // the loss's scale, pixels
  // Outlier rejection: after a solve, corners farther than the rule's
  // threshold from their projection are left out and the solve repeated
  // while that changes (at most 5 rounds). With kSigma the threshold is
  // max(outlier_sigma * sigma, outlier_min_px).
  OutlierRule outliers = OutlierRule::kChauvenet;
  double outlier_sigma = 6;
  double outlier_min_px = 0.25;

  int min_views = 3;         // per camera
  int min_stereo_views = 3;  // views where both cameras see the board
  int min_points_per_view = 6;
  double min_view_angle_deg = 5.0;  // the board normals must spread at least this much
  StereoFlow flow = StereoFlow::kJoint;
  bool covariance = true;  // parameter standard deviations
  FieldRule nonradial = FieldRule::kAuto;
  int field_cols = 0, field_rows = 0;  // FieldRule::kGrid
  bool field_tilt = false;             // FieldRule::kGrid
  // The board's deflection (board_warp.h): estimated with each camera's
  // final solve and the joint solve, held flat, or chosen (WarpRule).
  WarpRule board_warp = WarpRule::kAuto;
  // Folds of the cross-validation (heldout.h) after every solve and for
  // --knots auto (fewer with fewer than two views a fold, heldout.h); 0
  // switches the held-out RMS off (auto then needs it: at least 2).
  int cv_folds = 5;
  int max_iterations = 100;
  int grid_rows = 6, grid_cols = 8;  // the residual pattern per image region
  // Receives one line per stage (initialisation, each solve, r_max), for
  // logs; empty for none. Called one line at a time (stage_log.h), from
  // whichever of the solver's threads.
  std::function<void(const std::string&)> progress;
};

// What one model's solve does, fixed once by its caller from the options:
// the model, whether the solve chooses a non-radial part (none while
// several models are compared: calibrate.h, CalibrateStereoAllModels), and
// what the stereo step takes from the model's radial solve where one came
// first. Whether the pairs were exposed together is the data's, not the
// lens's: the radial solve's judgement stands for its field.
struct RadialStates;  // mono_solve.h
struct AngleStarts;   // calib/start/angle_start.h

struct ModelPlan {
  ModelKind model = ModelKind::kBspline;
  FieldRule nonradial = FieldRule::kAuto;
  // The options' own, or the paper's where the radial solve left the joint
  // solve out.
  StereoFlow flow = StereoFlow::kJoint;
  // The pairs the radial solve found no rig explains (stereo_solve.h); none:
  // judged in this solve.
  std::optional<std::vector<int>> unpaired;
  // Each camera's solve as it stood before its field (mono_solve.h): kept
  // into *keep_radial, or resumed from *from_radial, so that the chosen
  // model's field does not solve its radial model again.
  std::shared_ptr<RadialStates> keep_radial;
  std::shared_ptr<const RadialStates> from_radial;
  // The angle models' start (angle_start.h), shared by the models solved
  // at once; none: each solves its own.
  std::shared_ptr<AngleStarts> angle_starts;
};
// The plan of the options' own model, non-radial rule and flow.
inline ModelPlan PlanAsAsked(const CalibrationOptions& options) {
  return {options.model, options.nonradial, options.flow, std::nullopt, nullptr, nullptr, nullptr};
}

// Throws CalibrationError for options no calibration can use (knots out of
// range, min_views below 3).
void CheckOptions(const CalibrationOptions& options);

// "auto" (empty) or a count from 2 to 64 (--knots, knots=N); throws
// std::invalid_argument otherwise.
std::optional<int> ParseKnots(const std::string& value);

// --nonradial: "auto", "none", "tilt", "COLSxROWS" or "tilt+COLSxROWS"
// (kGrid, 4 to 64 each) into options->nonradial, field_tilt, field_cols,
// field_rows; throws std::invalid_argument otherwise.
void ParseFieldRule(const std::string& value, CalibrationOptions* options);

// --outlier-sigma: "auto" (kChauvenet), "off" or "0" (kOff), or a positive
// number K (kSigma, K into *sigma); throws std::invalid_argument otherwise.
OutlierRule ParseOutlierRule(const std::string& value, double* sigma);

}  // namespace ws::calib
