#include "calib/solver/outliers.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "calib/solver/corner_noise.h"

namespace ws::calib {
namespace {

constexpr int kMaxRounds = 5;
// OutlierRule::kChauvenet's two levels, as expected counts of noise corners
// beyond them (options.h).
constexpr double kChauvenetCorners = 0.5, kAlarmCorners = 0.01;

// The level |e| that N corners of Gaussian noise sigma (per coordinate)
// exceed `expected` times in all: N exp(-t^2 / 2 sigma^2) = expected.
double Level(double sigma, size_t corners, double expected) {
  return sigma * std::sqrt(2.0 * std::log(corners / expected));
}

// The median detection noise of camera `camera`'s views (corner_noise.h).
double DetectionNoise(const Problem& problem, int camera) {
  std::vector<const BoardView*> views;
  for (const Observation& o : problem.observations)
    if (o.camera == camera) views.push_back(o.corners);
  return MedianCornerNoise(views);
}

// Decides anew which of camera `camera`'s corners are outliers (their
// inlier flag cleared) and which are not (options.h, OutlierRule), its
// views' detection noise `noise_px` (DetectionNoise: the same in every
// round, the corners do not move); returns how many flags changed.
int RejectOutliers(Problem& problem, int camera, const RejectionSettings& options, double noise_px) {
  std::vector<CornerResidual> residuals = Residuals(problem, camera);
  double threshold = 0;
  if (options.outliers == OutlierRule::kSigma) {
    threshold = std::max(options.outlier_sigma * RobustSigma(residuals), options.outlier_min_px);
  } else {
    const double sigma = std::max(RmsSigma(residuals), noise_px);
    const double alarm = Level(sigma, residuals.size(), kAlarmCorners);
    const bool alarmed = std::any_of(residuals.begin(), residuals.end(), [&](const auto& r) {
      return !r.outlier && !(r.residual.norm() <= alarm);
    });
    if (!alarmed) return 0;
    threshold = Level(sigma, residuals.size(), kChauvenetCorners);
  }
  const int changed = MarkOutliers(residuals, threshold);
  if (changed == 0) return 0;
  for (const CornerResidual& r : residuals)
    for (Observation& o : problem.observations)
      if (o.camera == camera && o.view == r.view) (*o.inliers)[r.index] = !r.outlier;
  return changed;
}

}  // namespace

SolveSettings StageSettings(const CalibrationOptions& options, const std::string& what,
                            int max_iterations) {
  return SolveSettings{what, max_iterations, options.robust_loss, options.robust_scale_px};
}

RejectionSettings RejectingOutliers(const CalibrationOptions& options, const std::string& what) {
  return {StageSettings(options, what, options.max_iterations), options.outliers,
          options.outlier_sigma, options.outlier_min_px};
}

RejectionSettings OnTheCorners(const CalibrationOptions& options, const std::string& what) {
  return {StageSettings(options, what, options.max_iterations)};
}

SolveOutcome SolveWithRejection(Problem& problem, const RejectionSettings& settings) {
  SolveOutcome outcome = Solve(problem, settings.solve);
  const bool reject = settings.outliers != OutlierRule::kOff;
  std::vector<double> noise_px(problem.cameras.size(), 0.0);
  if (settings.outliers == OutlierRule::kChauvenet)
    for (size_t c = 0; c < problem.cameras.size(); ++c)
      if (!problem.cameras[c].fixed) noise_px[c] = DetectionNoise(problem, int(c));
  for (int round = 0; reject && round < kMaxRounds; ++round) {
    int changed = 0;
    for (size_t c = 0; c < problem.cameras.size(); ++c)
      if (!problem.cameras[c].fixed) changed += RejectOutliers(problem, int(c), settings, noise_px[c]);
    if (changed == 0) break;
    outcome = Solve(problem, settings.solve);
  }
  return outcome;
}

}  // namespace ws::calib
