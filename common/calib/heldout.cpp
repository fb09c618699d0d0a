#include "calib/heldout.h"

#include <cmath>
#include <algorithm>
#include <limits>
#include <map>
#include <numeric>

#include <opencv2/core/utility.hpp>

#include "calib/pose_fit.h"

namespace ws::calib {

CameraBlock FixedBlock(const CameraModel& model) {
  CameraBlock block(MakeModel(model.distortion, Coefficients::kIdentifiable));
  block.intrinsics = model.Intrinsics();
  block.coeffs = std::visit([&](const auto& m) { return m.EstimatedCoeffs(model.distortion.coeffs); },
                            block.model);
  block.fixed = true;
  return block;
}

HeldOutFit FitHeldOutViews(const CameraModel& model, const CameraData& data, int min_points,
                           const BoardWarp& warp) {
  const CameraBlock camera = FixedBlock(model);
  HeldOutFit fit;
  fit.view_rms.assign(data.views.size(), -1.0);
  double sum = 0;
  for (size_t v = 0; v < data.views.size(); ++v) {
    const BoardView& view = data.views[v];
    if (view.size() < min_points) continue;
    const std::vector<char> all(view.size(), 1);
    double best = std::numeric_limits<double>::infinity();
    for (Pose pose : PlanarPoseCandidates(camera, view, all))
      best = std::min(best, RefinePose(camera, view, all, &pose, warp));
    if (!std::isfinite(best)) continue;
    fit.view_rms[v] = best;
    sum += best * best * view.size();
    fit.points += view.size();
    ++fit.views;
  }
  fit.rms_px = fit.points > 0 ? std::sqrt(sum / fit.points) : 0.0;
  return fit;
}

namespace {

// The problem's observations whose view is (or, with keep = false, is not)
// in `views`, on the board poses of *poses (copies of the problem's, one per
// distinct pose the problem points to).
Problem Subproblem(const Problem& solved, const std::vector<int>& views, bool keep,
                   const std::map<const Pose*, size_t>& index, std::vector<Pose>* poses) {
  Problem out = solved;
  out.observations.clear();
  out.left_out.clear();
  for (Observation o : solved.observations) {
    if (std::binary_search(views.begin(), views.end(), o.view) != keep) continue;
    o.pose = &(*poses)[index.at(o.pose)];
    out.observations.push_back(o);
  }
  return out;
}

// One fold's held-out residuals per camera (sum of squares, count), or none
// when leaving it out leaves a camera without enough views.
struct FoldResult {
  bool solved = false;
  std::vector<double> sum;
  std::vector<int> count;
};

FoldResult SolveFold(const Problem& solved, const std::vector<int>& held,
                     const std::map<const Pose*, size_t>& index, const std::vector<Pose>& start,
                     int k, int max_iterations) {
  FoldResult out;
  std::vector<Pose> poses = start;
  Problem train = Subproblem(solved, held, false, index, &poses);
  const std::string what = "cross-validation fold " + std::to_string(k + 1);
  try {
    SolveSettings settings{what, std::min(kFoldIterations, max_iterations)};
    settings.tolerance = kRankingTolerance;
    Solve(train, settings);
    settings.max_iterations = max_iterations;  // the held-out poses, each from the full solution's
    Problem test = Subproblem(solved, held, true, index, &poses);
    test.cameras = train.cameras;
    for (CameraBlock& camera : test.cameras) camera.fixed = true;
    test.extrinsic = train.extrinsic;
    test.extrinsic_fixed = true;
    settings.what = what + " held-out poses";
    Solve(test, settings);
    for (size_t c = 0; c < solved.cameras.size(); ++c) {
      double sum = 0;
      int count = 0;
      for (const CornerResidual& r : Residuals(test, int(c)))
        if (!r.outlier && r.residual.allFinite()) {
          sum += r.residual.squaredNorm();
          ++count;
        }
      out.sum.push_back(sum);
      out.count.push_back(count);
    }
    out.solved = true;
  } catch (const CalibrationError&) {
    // A fold that leaves a camera without enough views: it counts as no fold.
  }
  return out;
}

}  // namespace

CrossValidation CrossValidate(const Problem& solved, int folds, int max_iterations) {
  std::vector<int> views;
  std::map<const Pose*, size_t> index;
  std::vector<Pose> start;
  for (const Observation& o : solved.observations) {
    views.push_back(o.view);
    if (index.emplace(o.pose, start.size()).second) start.push_back(*o.pose);
  }
  std::sort(views.begin(), views.end());
  views.erase(std::unique(views.begin(), views.end()), views.end());
  CrossValidation cv;
  const int n_cameras = int(solved.cameras.size());
  if (folds < 2 || int(views.size()) < 2 * folds) return cv;
  // The folds are independent solves: on every core (OpenCV's pool), each
  // fold's result kept in its place, so the outcome does not depend on the
  // order they finish in.
  std::vector<FoldResult> results(folds);
  cv::parallel_for_(
      cv::Range(0, folds),
      [&](const cv::Range& range) {
        for (int k = range.start; k < range.end; ++k) {
          std::vector<int> held;
          for (size_t i = k; i < views.size(); i += folds) held.push_back(views[i]);
          results[k] = SolveFold(solved, held, index, start, k, max_iterations);
        }
      },
      folds);
  std::vector<double> sum(n_cameras, 0.0);
  std::vector<int> count(n_cameras, 0);
  cv.fold_rms_px.assign(n_cameras, {});
  for (const FoldResult& fold : results) {
    if (!fold.solved) continue;
    for (int c = 0; c < n_cameras; ++c) {
      sum[c] += fold.sum[c];
      count[c] += fold.count[c];
      cv.fold_rms_px[c].push_back(fold.count[c] ? std::sqrt(fold.sum[c] / fold.count[c]) : 0.0);
    }
    ++cv.folds;
  }
  for (int c = 0; c < n_cameras; ++c)
    cv.rms_px.push_back(count[c] ? std::sqrt(sum[c] / count[c]) : -1.0);
  if (cv.folds < 2) cv = CrossValidation{};
  return cv;
}

int ChooseWithinNoise(const std::vector<std::vector<double>>& fold_rms) {
  if (fold_rms.empty()) return -1;
  size_t folds = fold_rms[0].size();
  for (const auto& f : fold_rms) folds = std::min(folds, f.size());
  auto mean = [&](const std::vector<double>& f) {
    return std::accumulate(f.begin(), f.begin() + folds, 0.0) / std::max<size_t>(folds, 1);
  };
  size_t best = 0;
  for (size_t i = 1; i < fold_rms.size(); ++i)
    if (mean(fold_rms[i]) < mean(fold_rms[best])) best = i;
  for (size_t i = 0; i < best; ++i) {
    std::vector<double> d(folds);
    for (size_t k = 0; k < folds; ++k) d[k] = fold_rms[i][k] - fold_rms[best][k];
    const double m = mean(d);
    double var = 0;
    for (double x : d) var += (x - m) * (x - m);
    const double se = folds > 1 ? std::sqrt(var / (folds - 1) / folds) : 0.0;
    if (m <= se) return int(i);
  }
  return int(best);
}

}  // namespace ws::calib
