#include "calib/start/equidistant_start.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "calib/solver/quality.h"
#include "calib/start/ray_pose.h"

namespace ws::calib {
namespace {

struct Fit {
  double score = std::numeric_limits<double>::infinity();  // median per-view RMS, pixels
  std::vector<Pose> poses;
  std::vector<bool> posed;
};

// Every usable view posed under the equidistant camera (f, c).
Fit Evaluate(const Prepared& p, double f, const Eigen::Vector2d& c, int min_views) {
  Fit fit;
  fit.poses.resize(p.views.size());
  fit.posed.assign(p.views.size(), false);
  std::vector<double> rms;
  for (size_t v = 0; v < p.views.size(); ++v) {
    if (!p.usable[v]) continue;
    const BoardView& view = p.views[v];
    std::vector<Eigen::Vector3d> object, rays;
    for (int i = 0; i < view.size(); ++i) {
      const Eigen::Vector2d x = (view.image[i] - c) / f;  // theta (cos phi, sin phi)
      const double theta = x.norm();
      if (!(theta < M_PI)) continue;
      const double sinc = theta > 1e-12 ? std::sin(theta) / theta : 1.0;
      object.push_back(view.object[i]);
      rays.emplace_back(sinc * x.x(), sinc * x.y(), std::cos(theta));
    }
    const auto pose = PoseFromRays(object, rays);
    if (!pose) continue;
    double sum = 0;
    for (int i = 0; i < view.size(); ++i) {
      const Eigen::Vector3d X = *pose * view.object[i];
      const double rho = X.head<2>().norm();
      const double scale = rho > 0 ? f * std::atan2(rho, X.z()) / rho : 0.0;
      sum += (c + scale * X.head<2>() - view.image[i]).squaredNorm();
    }
    fit.poses[v] = *pose;
    fit.posed[v] = true;
    rms.push_back(std::sqrt(sum / view.size()));
  }
  if (static_cast<int>(rms.size()) < min_views) return fit;
  fit.score = Median(rms);
  return fit;
}

}  // namespace

PinholeInit EquidistantStart(const Prepared& p, int min_views, std::vector<Pose>* poses,
                             std::vector<bool>* posed) {
  const Eigen::Vector2d centre((p.width - 1) / 2.0, (p.height - 1) / 2.0);
  const double half_diagonal = 0.5 * std::hypot(p.width, p.height);
  // From a 360-degree circle inside the image to a narrow lens: f from
  // 0.05 to 5 half-diagonals in steps of 10 %, then 1 % about the best.
  double best_f = 0;
  Fit best;
  auto consider = [&](double f) {
    Fit fit = Evaluate(p, f, centre, min_views);
    if (fit.score < best.score) {
      best = std::move(fit);
      best_f = f;
    }
  };
  for (double f = 0.05 * half_diagonal; f <= 5 * half_diagonal; f *= 1.1) consider(f);
  if (!std::isfinite(best.score))
    throw CalibrationError(p.name + " camera: no equidistant start poses " +
                           std::to_string(min_views) + " views of the board");
  const double coarse = best_f;
  for (double f = coarse / 1.1; f <= coarse * 1.1; f *= 1.01) consider(f);
  *poses = best.poses;
  *posed = best.posed;
  return PinholeInit{best_f, best_f, centre.x(), centre.y(), "equidistant"};
}

}  // namespace ws::calib
