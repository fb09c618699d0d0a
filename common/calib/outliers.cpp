#include "calib/outliers.h"

namespace ws::calib {
namespace {

constexpr int kMaxRounds = 5;

// Decides anew which of camera `camera`'s corners are outliers (their
// inlier flag cleared) and which are not; returns how many flags changed.
int RejectOutliers(Problem& problem, int camera, const CalibrationOptions& options) {
  std::vector<CornerResidual> residuals = Residuals(problem, camera);
  const int changed = MarkOutliers(residuals, options.outlier_sigma, options.outlier_min_px);
  if (changed == 0) return 0;
  for (const CornerResidual& r : residuals)
    for (Observation& o : problem.observations)
      if (o.camera == camera && o.view == r.view) (*o.inliers)[r.index] = !r.outlier;
  return changed;
}

}  // namespace

SolveOutcome SolveWithRejection(Problem& problem, const CalibrationOptions& options,
                                const std::string& what) {
  const SolveSettings settings{what, options.max_iterations, options.robust_loss,
                               options.robust_scale_px};
  SolveOutcome outcome = Solve(problem, settings);
  for (int round = 0; options.outlier_sigma > 0 && round < kMaxRounds; ++round) {
    int changed = 0;
    for (size_t c = 0; c < problem.cameras.size(); ++c)
      if (!problem.cameras[c].fixed) changed += RejectOutliers(problem, int(c), options);
    if (changed == 0) break;
    outcome = Solve(problem, settings);
  }
  if (options.covariance) EstimateStddev(problem, settings, &outcome);
  return outcome;
}

}  // namespace ws::calib
