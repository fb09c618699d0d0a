#include "calib/outliers.h"

namespace ws::calib {
namespace {

// Clears the inlier flag of camera `camera`'s outliers; returns how many.
int RejectOutliers(Problem& problem, int camera, const CalibrationOptions& options) {
  std::vector<CornerResidual> residuals = Residuals(problem, camera);
  const int marked = MarkOutliers(residuals, options.outlier_sigma, options.outlier_min_px);
  if (marked == 0) return 0;
  for (const CornerResidual& r : residuals) {
    if (!r.outlier) continue;
    for (Observation& o : problem.observations)
      if (o.camera == camera && o.view == r.view) (*o.inliers)[r.index] = 0;
  }
  return marked;
}

}  // namespace

SolveOutcome SolveWithRejection(Problem& problem, const CalibrationOptions& options,
                                const std::string& what) {
  const SolveSettings settings{what, options.max_iterations, options.robust_loss,
                               options.robust_scale_px};
  SolveOutcome outcome = Solve(problem, settings);
  for (int round = 0; options.outlier_sigma > 0 && round < 3; ++round) {
    int marked = 0;
    for (size_t c = 0; c < problem.cameras.size(); ++c)
      if (!problem.cameras[c].fixed) marked += RejectOutliers(problem, int(c), options);
    if (marked == 0) break;
    outcome = Solve(problem, settings);
  }
  if (options.covariance) EstimateStddev(problem, settings, &outcome);
  return outcome;
}

}  // namespace ws::calib
