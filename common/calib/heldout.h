// How well a calibrated camera predicts views it was not fitted to
// (BabelCalib's train/test protocol, Lochman et al. 2021, Sec. 5): the
// camera held fixed, each view's board pose fitted alone to its corners, and
// the RMS of all those corners' residuals; and the same inside one solve,
// K-fold over its views.
#pragma once

#include <vector>

#include "calib/board_warp.h"
#include "calib/calib_data.h"
#include "calib/camera_block.h"
#include "calib/problem.h"
#include "models/camera_model.h"

namespace ws::calib {

struct HeldOutFit {
  double rms_px = 0;             // over every corner of the posed views
  int views = 0;                 // views a pose was found for
  int points = 0;
  std::vector<double> view_rms;  // per view; negative where no pose fits
};

// A stored camera as the solver's block (its estimated coefficients), fixed.
CameraBlock FixedBlock(const CameraModel& model);

// Every non-empty view with at least min_points corners posed under the
// fixed camera and board shape (a calibration's board_warp; flat by
// default): from each planar start (pose_fit.h), refined, the best kept.
HeldOutFit FitHeldOutViews(const CameraModel& camera, const CameraData& views, int min_points = 6,
                           const BoardWarp& warp = BoardWarp());

// K-fold cross-validation of a solved problem (issue #14). The problem's
// views are dealt round-robin, in view order, into `folds` folds (a stereo
// view's two images are one view, so they stay together). For each fold the
// problem is solved again without it, warm-started at the full solution
// (the same cameras, extrinsic and poses, no outlier rejection, the
// inliers as they are); then, with every camera parameter and the extrinsic
// held at that fold's solution, only the held-out views' board poses are
// fitted (each starting at its pose in the full solution) and their
// corners' residuals kept: the held-out residuals. The folds are solved in
// parallel on OpenCV's thread pool (cv::setNumThreads bounds it); the result
// does not depend on it.
struct CrossValidation {
  int folds = 0;  // 0: not enough views (fewer than 2 per fold) or not asked
  // Per camera of the problem: the RMS of every held-out residual of every
  // fold, and each fold's own RMS (fold order; the fold-to-fold noise).
  std::vector<double> rms_px;
  std::vector<std::vector<double>> fold_rms_px;
};
//
// A fold's training solve takes at most kFoldIterations Levenberg-Marquardt
// steps: from the full solution the fold's optimum (a fifth of the views
// fewer) is a small step away, which Gauss-Newton takes to second order;
// a few more steps absorb rejected ones. Measured against folds solved to
// convergence: on the mustache rig (bench/calib) every knot count's held-out
// RMS agrees to 1e-5 px at 3 steps (3e-5 px at 1); on fisheye-stereo-ros
// (real corners, 0.4 px noise) to 1e-4 px at 5 steps, while 2 steps moved
// them by up to 4e-4 px, enough to flip a choice that sits on the edge of
// the fold-to-fold noise (kb4 against bspline_theta).
inline constexpr int kFoldIterations = 5;
// The held-out poses are solved with up to `max_iterations` steps.
CrossValidation CrossValidate(const Problem& solved, int folds, int max_iterations);

// Of candidates in order of complexity, each with its per-fold held-out RMS
// (the same folds for all), the least complex whose excess over the best
// (the lowest mean) is within the fold-to-fold noise: mean_k(e_k - best_k)
// <= its standard error, sd_k(e_k - best_k) / sqrt(K). The paired
// difference cancels what the folds share (which views, how noisy).
// Returns an index into `fold_rms`; -1 when it is empty.
int ChooseWithinNoise(const std::vector<std::vector<double>>& fold_rms);

}  // namespace ws::calib
