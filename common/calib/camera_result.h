// A solved camera as the caller sees it (CameraCalibration, calibrate.h):
// the stored model, its residuals and quality, and the checks that keep a
// garbage result from leaving the solver.
#pragma once

#include <string>
#include <vector>

#include "calib/calibrate.h"
#include "calib/evaluate/heldout.h"
#include "calib/solver/problem.h"
#include "calib/start/initialise.h"

namespace ws::calib {

// Camera `camera` of the solved problem, over the views of `prepared`.
// Throws CalibrationError when its distortion curve folds back inside the
// observed field (r (1 + D(r)) not increasing: two directions on one pixel)
// or fewer than options.min_views views fit it.
// The standard deviations are the outcome's (of this problem's solve).
CameraCalibration CameraResult(const Problem& problem, int camera, const Prepared& prepared,
                               const SolveOutcome& outcome, const std::string& init_method,
                               const CalibrationOptions& options);

// Throws CalibrationError when camera `camera`'s distortion curve folds
// back inside the field its inlier corners reach under their board poses
// (r (1 + D(r)) not increasing: two directions on one pixel); `name` is the
// camera's. Returns that reach, the largest ideal radius.
double RequireUnfolded(const Problem& problem, int camera, const std::string& name);

// Camera `camera`'s held-out RMS of a cross-validation (none when it has no
// folds) into *out.
void SetHeldOut(const CrossValidation& cv, int camera, CameraCalibration* out);

}  // namespace ws::calib
