// How well a calibrated camera predicts views it was not fitted to
// (BabelCalib's train/test protocol, Lochman et al. 2021, Sec. 5): the
// camera held fixed, each view's board pose fitted alone to its corners, and
// the RMS of all those corners' residuals; and the same inside one solve,
// K-fold over its views.
#pragma once

#include <string>
#include <vector>

#include "calib/evaluate/heldout_corner.h"
#include "calib/evaluate/selection.h"
#include "calib/solver/board_warp.h"
#include "calib/solver/calib_data.h"
#include "calib/solver/camera_block.h"
#include "calib/solver/problem.h"
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
// problem without it is solved by one Gauss-Newton step from the full
// solution (the same cameras, extrinsic and poses, no outlier rejection, the
// inliers as they are; the other views' poses eliminated by the Schur
// complement); then, with every camera parameter and the extrinsic held at
// that step, each held-out view's board pose is refitted to its corners
// (one Gauss-Newton step from its pose in the full solution), and those
// corners' residuals are kept: the held-out residuals. A held-out corner
// farther from its camera's principal point than every corner of the
// training views is left out (and counted): there the fold's model only
// extrapolates, and how the smoothness prior continues a curve past the
// data says nothing of how well the model follows the lens. (On the
// sharp-knee rig one view alone reaches the left image's far corner; its
// outer corners decided --knots auto for a stiff 13-coefficient curve,
// 1.1-1.7 px off the truth, in two of eight noise draws.)
//
// One step, because the fold's optimum is a small step away: the full
// solution minimises the sum over all views, so without a fifth of them the
// gradient is that fifth's, and Gauss-Newton takes it to second order. The
// whole cross-validation then costs one Jacobian of the solved problem and
// one small dense solve per fold, not K solves. Measured against the folds
// it replaces (five Levenberg-Marquardt steps each, then the held-out poses
// solved) in docs/calibration.md: equal to 1e-4 px near the chosen count;
// a model far from the lens or not determined by its views reads higher,
// since the step is not damped.
struct CrossValidation {
  // The folds used: those asked for, fewer where there are fewer than two
  // views a fold (one a pair of views); 0: fewer than 4 views, or not asked.
  int folds = 0;
  // Per camera of the problem: the RMS of every held-out residual of every
  // fold, and each fold's own RMS (fold order; the fold-to-fold noise).
  std::vector<double> rms_px;
  std::vector<std::vector<double>> fold_rms_px;
  std::vector<int> extrapolated;  // per camera: held-out corners left out (above)
  std::vector<HeldOutCorner> corners;  // every held-out corner
};
// Throws CalibrationError if the solved problem cannot be evaluated.
CrossValidation CrossValidate(const Problem& solved, int folds);

// Candidates that left out different outliers (other models) compared on
// the same corners: per candidate, camera `camera`'s per-fold RMS over the
// held-out corners that every candidate kept (*corners: how many). Folds as
// the first candidate dealt them.
std::vector<std::vector<double>> FoldRmsOnCommonCorners(
    const std::vector<const std::vector<HeldOutCorner>*>& candidates, int camera,
    int* corners = nullptr);

// A candidate of selection.h scored by camera `camera`'s part of a
// cross-validation: its pooled and per-fold held-out RMS and its corners;
// failed where it has none.
Candidate Scored(std::string name, int parameters, const CrossValidation& cv, int camera);

}  // namespace ws::calib
