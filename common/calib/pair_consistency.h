// Whether a rig's stereo pairs fit one rigid, synchronised rig: with a
// hand-held board and cameras not triggered together, the board moves
// between the two exposures, and a pair's right image no longer sits where
// R, T put the left's board.
//
// Seeing the board of view v through R, T instead of with the right
// camera's own pose takes 6 degrees of freedom from it, so for a consistent
// pair the rise of its cost (squared residuals over the per-coordinate
// noise variance of each camera's own solve) is chi-square with 6 degrees of
// freedom, times a variance inflation s that real data show (model misfit
// and detection errors are not independent noise). s is estimated from the
// pairs themselves, median rise / 5.35 (the chi-square-6 median), at least 1;
// a pair rising beyond s times the 5-sigma quantile (39.49, p = 5.7e-7) is
// inconsistent. No pixel figure is assumed: the data say what a consistent
// pair costs.
#pragma once

#include <vector>

#include "calib/mono_solve.h"
#include "calib/solver/problem.h"

namespace ws::calib {

struct PairConsistency {
  std::vector<double> rise;       // per view (0 where not a stereo view)
  double inflation = 1;           // s
  std::vector<int> inconsistent;  // views
};

// `through_rig` holds the stereo views with the right camera on the left's
// board pose through R, T; `mono` each camera's own solve.
PairConsistency CheckPairs(const Problem& through_rig, const MonoState (&mono)[2],
                           const std::vector<bool>& is_stereo);

// Whether a joint solve (shared board poses for `pairs` stereo views) fits
// both cameras as well as each fits alone, within what sharing costs under
// each camera's own noise: its total rise below the chi-square-(6 pairs)
// 5-sigma quantile (normal approximation, 6 pairs + 5 sqrt(12 pairs)). Pairs
// exposed together pass; a rig whose pairs all moved a little does not.
bool JointFitsAsWellAsAlone(const Problem& joint, const MonoState (&mono)[2], int pairs);

}  // namespace ws::calib
