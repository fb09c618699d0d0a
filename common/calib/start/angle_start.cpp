#include "calib/start/angle_start.h"

#include <algorithm>
#include <cmath>
#include <future>
#include <limits>
#include <opencv2/core/utility.hpp>
#include <utility>

#include "calib/solver/quality.h"
#include "calib/start/ray_pose.h"
#include "models/radial_coordinate.h"

namespace ws::calib {
namespace {

struct Fit {
  double score = std::numeric_limits<double>::infinity();  // median per-view RMS, pixels
  std::vector<Pose> poses;
  std::vector<bool> posed;
};

// Every usable view posed under the lens (f, c): Coordinate's camera with
// D = 0 (radial_coordinate.h: Theta, the equidistant fisheye; TanTheta, the
// pinhole).
template <class Coordinate>
Fit EvaluateOn(const Prepared& p, double f, const Eigen::Vector2d& c, int min_views) {
  Fit fit;
  fit.poses.resize(p.views.size());
  fit.posed.assign(p.views.size(), false);
  std::vector<double> rms;
  for (size_t v = 0; v < p.views.size(); ++v) {
    if (!p.usable[v]) continue;
    const BoardView& view = p.views[v];
    std::vector<Eigen::Vector3d> object, rays;
    for (int i = 0; i < view.size(); ++i) {
      const Eigen::Vector2d ideal = (view.image[i] - c) / f;
      Eigen::Vector3d ray;
      if (!Coordinate::Ray(ideal.data(), ray.data())) continue;
      object.push_back(view.object[i]);
      rays.push_back(ray);
    }
    const auto pose = PoseFromRays(object, rays);
    if (!pose) continue;
    double sum = 0;
    for (int i = 0; i < view.size() && std::isfinite(sum); ++i) {
      const Eigen::Vector3d X = *pose * view.object[i];
      Eigen::Vector2d ideal;
      if (Coordinate::Ideal(X.data(), ideal.data()))
        sum += (c + f * ideal - view.image[i]).squaredNorm();
      else  // a corner the lens cannot see
        sum = std::numeric_limits<double>::infinity();
    }
    if (!std::isfinite(sum)) continue;
    fit.poses[v] = *pose;
    fit.posed[v] = true;
    rms.push_back(std::sqrt(sum / view.size()));
  }
  if (static_cast<int>(rms.size()) < min_views) return fit;
  fit.score = Median(rms);
  return fit;
}

Fit Evaluate(const Prepared& p, StartLens lens, double f, const Eigen::Vector2d& c,
             int min_views) {
  return lens == StartLens::kEquidistant ? EvaluateOn<Theta>(p, f, c, min_views)
                                         : EvaluateOn<TanTheta>(p, f, c, min_views);
}

// The fit of each (lens, f), solved on every core (threads of their own:
// OpenCV's pool runs a nested loop on one).
std::vector<Fit> EvaluateAll(const Prepared& p, const std::vector<std::pair<StartLens, double>>& grid,
                             const Eigen::Vector2d& c, int min_views) {
  std::vector<Fit> fits(grid.size());
  const size_t cores = size_t(std::max(1, cv::getNumThreads()));
  auto part = [&](size_t first) {
    for (size_t i = first; i < grid.size(); i += cores)
      fits[i] = Evaluate(p, grid[i].first, grid[i].second, c, min_views);
  };
  std::vector<std::future<void>> others;
  for (size_t first = 1; first < cores; ++first) others.push_back(std::async(std::launch::async, part, first));
  part(0);
  for (std::future<void>& other : others) other.get();
  return fits;
}

}  // namespace

AngleStartFit AngleStart(const Prepared& p, int min_views) {
  const Eigen::Vector2d centre((p.width - 1) / 2.0, (p.height - 1) / 2.0);
  const double half_diagonal = 0.5 * std::hypot(p.width, p.height);
  AngleStartFit best_start;
  Fit best;
  // The first of the grid's least score, as if it were tried in order.
  auto consider = [&](const std::vector<std::pair<StartLens, double>>& grid) {
    std::vector<Fit> fits = EvaluateAll(p, grid, centre, min_views);
    for (size_t i = 0; i < grid.size(); ++i)
      if (fits[i].score < best.score) {
        best = std::move(fits[i]);
        best_start.lens = grid[i].first;
        best_start.pinhole.fx = grid[i].second;
      }
  };
  // From a 360-degree circle inside the image to a narrow lens: f from
  // 0.05 to 5 half-diagonals in steps of 10 %, then 1 % about the best.
  std::vector<std::pair<StartLens, double>> coarse_grid, fine_grid;
  for (StartLens lens : {StartLens::kEquidistant, StartLens::kPerspective})
    for (double f = 0.05 * half_diagonal; f <= 5 * half_diagonal; f *= 1.1) coarse_grid.push_back({lens, f});
  consider(coarse_grid);
  if (!std::isfinite(best.score))
    throw CalibrationError(p.name + " camera: no equidistant or perspective start poses " +
                           std::to_string(min_views) + " views of the board");
  const double coarse = best_start.pinhole.fx;
  for (double f = coarse / 1.1; f <= coarse * 1.1; f *= 1.01) fine_grid.push_back({best_start.lens, f});
  consider(fine_grid);
  const double f = best_start.pinhole.fx;
  best_start.pinhole = PinholeInit{
      f, f, centre.x(), centre.y(),
      best_start.lens == StartLens::kEquidistant ? "equidistant" : "perspective"};
  best_start.poses = std::move(best.poses);
  best_start.posed = std::move(best.posed);
  return best_start;
}

const AngleStartFit& SharedAngleStart::Get(const Prepared& prepared, int min_views) {
  std::call_once(once_, [&] { fit_ = AngleStart(prepared, min_views); });
  return fit_;
}

}  // namespace ws::calib
