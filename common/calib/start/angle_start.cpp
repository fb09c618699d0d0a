#include "calib/start/angle_start.h"

#include <cmath>
#include <limits>

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

}  // namespace

AngleStartFit AngleStart(const Prepared& p, int min_views) {
  const Eigen::Vector2d centre((p.width - 1) / 2.0, (p.height - 1) / 2.0);
  const double half_diagonal = 0.5 * std::hypot(p.width, p.height);
  AngleStartFit best_start;
  Fit best;
  auto consider = [&](StartLens lens, double f) {
    Fit fit = Evaluate(p, lens, f, centre, min_views);
    if (fit.score < best.score) {
      best = std::move(fit);
      best_start.lens = lens;
      best_start.pinhole.fx = f;
    }
  };
  // From a 360-degree circle inside the image to a narrow lens: f from
  // 0.05 to 5 half-diagonals in steps of 10 %, then 1 % about the best.
  for (StartLens lens : {StartLens::kEquidistant, StartLens::kPerspective})
    for (double f = 0.05 * half_diagonal; f <= 5 * half_diagonal; f *= 1.1) consider(lens, f);
  if (!std::isfinite(best.score))
    throw CalibrationError(p.name + " camera: no equidistant or perspective start poses " +
                           std::to_string(min_views) + " views of the board");
  const double coarse = best_start.pinhole.fx;
  for (double f = coarse / 1.1; f <= coarse * 1.1; f *= 1.01) consider(best_start.lens, f);
  const double f = best_start.pinhole.fx;
  best_start.pinhole = PinholeInit{
      f, f, centre.x(), centre.y(),
      best_start.lens == StartLens::kEquidistant ? "equidistant" : "perspective"};
  best_start.poses = std::move(best.poses);
  best_start.posed = std::move(best.posed);
  return best_start;
}

}  // namespace ws::calib
