// Outlier rejection around a solve: corners that a solved camera misses by
// far more than the noise it shows are marked (their inlier flag cleared)
// and the problem solved again; every round decides every corner anew, so a
// good corner that a first fit, pulled by the outliers, missed comes back.
#pragma once

#include <string>

#include "calib/solver/options.h"
#include "calib/solver/problem.h"

namespace ws::calib {

// Solves the problem; unless options.outliers is kOff it then decides each
// free camera's outliers (MarkOutliers in quality.h) and solves again while
// the decision changes, at most 5 rounds; last, with options.covariance,
// the standard deviations.
SolveOutcome SolveWithRejection(Problem& problem, const CalibrationOptions& options,
                                const std::string& what);

}  // namespace ws::calib
