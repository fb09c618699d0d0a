#include "calib/start/angle_start.h"

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

// theta of an ideal radius x = r / f, and r / f of a ray at theta from the
// axis (infinite where the lens has no image of it).
double Theta(StartLens lens, double x) {
  return lens == StartLens::kEquidistant ? x : std::atan(x);
}
double Height(StartLens lens, double theta) {
  if (lens == StartLens::kEquidistant) return theta;
  return theta < M_PI / 2 ? std::tan(theta) : std::numeric_limits<double>::infinity();
}

// Every usable view posed under the lens (f, c).
Fit Evaluate(const Prepared& p, StartLens lens, double f, const Eigen::Vector2d& c,
             int min_views) {
  Fit fit;
  fit.poses.resize(p.views.size());
  fit.posed.assign(p.views.size(), false);
  std::vector<double> rms;
  for (size_t v = 0; v < p.views.size(); ++v) {
    if (!p.usable[v]) continue;
    const BoardView& view = p.views[v];
    std::vector<Eigen::Vector3d> object, rays;
    for (int i = 0; i < view.size(); ++i) {
      const Eigen::Vector2d x = (view.image[i] - c) / f;  // (r / f) (cos phi, sin phi)
      const double theta = Theta(lens, x.norm());
      if (!(theta < M_PI)) continue;
      const double scale = x.norm() > 1e-12 ? std::sin(theta) / x.norm() : 1.0;
      object.push_back(view.object[i]);
      rays.emplace_back(scale * x.x(), scale * x.y(), std::cos(theta));
    }
    const auto pose = PoseFromRays(object, rays);
    if (!pose) continue;
    double sum = 0;
    for (int i = 0; i < view.size(); ++i) {
      const Eigen::Vector3d X = *pose * view.object[i];
      const double rho = X.head<2>().norm();
      const double scale = rho > 0 ? f * Height(lens, std::atan2(rho, X.z())) / rho : 0.0;
      sum += (c + scale * X.head<2>() - view.image[i]).squaredNorm();
    }
    if (!std::isfinite(sum)) continue;  // a corner the lens cannot see
    fit.poses[v] = *pose;
    fit.posed[v] = true;
    rms.push_back(std::sqrt(sum / view.size()));
  }
  if (static_cast<int>(rms.size()) < min_views) return fit;
  fit.score = Median(rms);
  return fit;
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
