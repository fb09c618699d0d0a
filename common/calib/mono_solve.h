// One camera's calibration from its own views (paper Sec. VI-B): Zhang's
// start, then a radial continuation to the full model.
//
// Boards at the periphery of a super-wide lens pull any fit that starts
// there far off, so the solve grows outwards: a pinhole fitted to the
// central corners only (within a quarter of the image's half-diagonal of
// the principal point, the disc growing until it holds enough views), where
// every lens is closest to a pinhole; then the full model on ever larger discs (x1.4);
// then all corners, with outlier rejection. Before each stage every view's
// pose is refitted alone with the camera as it stands (pose_fit.h). For a
// B-spline the knots span [0, r_max], r_max the image's corner radius under
// the camera (times a margin), placed again once the distortion is known.
// With --knots auto the number of coefficients is then chosen by
// cross-validation (options.h, SplineOptions::knots empty).
#pragma once

#include <string>
#include <vector>

#include "calib/calibrate.h"
#include "calib/evaluate/heldout.h"
#include "calib/evaluate/selection.h"
#include "calib/solver/options.h"
#include "calib/solver/problem.h"
#include "calib/start/initialise.h"

namespace ws::calib {

// Everything one camera's solve keeps. The problem points into prepared,
// inliers and poses: a MonoState is solved in place and not copied after.
struct MonoState {
  Prepared prepared;
  Inliers inliers;          // per view, per corner: used (outliers cleared)
  std::vector<Pose> poses;  // board -> camera, per view
  BoardWarp warp;           // the board as the last solve left it (flat unless estimated)
  Problem problem;          // the last solve: the camera and its usable views
  SolveOutcome outcome;
  std::string init_method;  // PinholeInit::method
  std::vector<KnotTrial> knot_curve;  // --knots auto: every count tried
  CrossValidation heldout;            // of the last solve, when --knots auto ran it
  WarpChoice warp_choice;             // --board-warp auto
  std::vector<FieldTrial> field_curve;  // --nonradial auto: "none", the tilt, then every field tried
  int field_chosen = 0;                 // its index in field_curve
  std::vector<Selection> selections;    // every choice made (selection.h), in order
};

// Both cameras' solves as they stood before the non-radial field (the
// model, its knots, outliers and the board's bow chosen): copies, whose
// problems SolveMono binds again to their own views before use.
struct RadialStates {
  MonoState camera[2];  // left, right
};

// Calibrates the camera of `data` with the model of `plan` into *state;
// `board` is the extent of the board (board_warp.h), the warp estimated in
// the final solve or chosen by the held-out RMS as options.board_warp says.
// `camera` is its slot in plan.keep_radial and plan.from_radial (0: left):
// with from_radial the radial solve is not repeated, its copy resumed.
// `cores`: how many trials of the knots' and the field's ladders may be solved at
// once (the knots' on threads of their own: beside another model's solve too).
// Throws CalibrationError.
void SolveMono(const CameraData& data, const BoardExtent& board, const CalibrationOptions& options,
               const ModelPlan& plan, MonoState* state, int camera = 0, int cores = 1);

// The cross-validation of the state's last solve: the one --knots auto made,
// else made now (options.cv_folds).
CrossValidation HeldOut(const MonoState& state, const CalibrationOptions& options);

}  // namespace ws::calib
