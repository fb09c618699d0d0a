// Outlier rejection around a solve: corners that a solved camera misses by
// far more than the noise it shows are marked (their inlier flag cleared)
// and the problem solved again; every round decides every corner anew, so a
// good corner that a first fit, pulled by the outliers, missed comes back.
#pragma once

#include <string>

#include "calib/solver/options.h"
#include "calib/solver/problem.h"

namespace ws::calib {

// One Levenberg-Marquardt solve of the stage `what` with the options'
// robust loss, at most max_iterations.
SolveSettings StageSettings(const CalibrationOptions& options, const std::string& what,
                            int max_iterations);

// How a solve's corners are judged: one stage's settings, built once from
// the options (RejectingOutliers, OnTheCorners).
struct RejectionSettings {
  SolveSettings solve;
  OutlierRule outliers = OutlierRule::kOff;
  double outlier_sigma = 6, outlier_min_px = 0.25;  // kSigma's
};

// The stage `what` deciding outliers as the options ask (a start's gross
// outliers, a camera's final solve).
RejectionSettings RejectingOutliers(const CalibrationOptions& options, const std::string& what);
// The stage `what` on the corners as they stand: no outlier decided, no
// standard deviations (candidates compared on the same corners, a stereo
// solve keeping each camera's decision).
RejectionSettings OnTheCorners(const CalibrationOptions& options, const std::string& what);

// Solves the problem; unless settings.outliers is kOff it then decides
// each free camera's outliers (MarkOutliers in quality.h) and solves again
// while the decision changes, at most 5 rounds.
SolveOutcome SolveWithRejection(Problem& problem, const RejectionSettings& settings);

}  // namespace ws::calib
