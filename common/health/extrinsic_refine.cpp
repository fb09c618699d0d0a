#include "health/extrinsic_refine.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>
#include <ceres/ceres.h>

#include "health/rectified_dy_residual.h"

namespace ws {
namespace {

constexpr double kDeg = 180 / M_PI;
constexpr int kTrimRounds = 2;        // solve, drop the gross outliers, solve again
constexpr double kTrimFloorPx = 1.0;

void AngleAxis(const Eigen::Matrix3d& R, double om[3]) {
  ceres::RotationMatrixToAngleAxis(R.data(), om);  // column-major, as Eigen stores it
}

Eigen::Matrix3d Rotation(const double om[3]) {
  Eigen::Matrix3d R;
  ceres::AngleAxisToRotationMatrix(om, R.data());  // column-major, as Eigen stores it
  return R;
}

std::string Spread(const std::vector<RayMatch>& matches, cv::Size size, const DyGrid& grid,
                   const RefineOptions& o) {
  std::vector<DyMatch> points;
  for (const RayMatch& m : matches) points.push_back({m.pixel, 0.f});
  const int regions = ComputeDyFigures(points, size, grid).regions_with(o.min_region_matches);
  if (int(matches.size()) < o.min_matches)
    return std::to_string(matches.size()) + " matches, fewer than the " + std::to_string(o.min_matches) +
           " refinement needs";
  if (regions < o.min_regions)
    return "the matches fill only " + std::to_string(regions) + " regions with " +
           std::to_string(o.min_region_matches) + " or more, fewer than " + std::to_string(o.min_regions) +
           ": not spread enough";
  return "";
}

// Levenberg-Marquardt from (om, t) over `matches`; false, with the reason,
// when the solver fails.
bool Solve(const std::vector<RayMatch>& matches, double f, double loss_px, double om[3], double t[3],
           std::string* why) {
  ceres::Problem problem;
  for (const RayMatch& m : matches)
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<RectifiedDyResidual, 1, 3, 3>(
                                 new RectifiedDyResidual(m.left.val, m.right.val, f)),
                             new ceres::HuberLoss(loss_px), om, t);
  problem.SetManifold(t, new ceres::SphereManifold<3>);
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = 50;
  options.function_tolerance = 1e-12;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  if (!summary.IsSolutionUsable()) *why = "the solver failed: " + summary.message;
  return summary.IsSolutionUsable();
}

// The matches whose |dy| under (om, t) is within max(kTrimFloorPx, 3 x the
// median): a match a board's square off (15 px or more) goes, which a Huber
// loss would still let pull.
std::vector<RayMatch> Trimmed(const std::vector<RayMatch>& matches, double f, const double om[3],
                              const double t[3]) {
  std::vector<double> abs_dy;
  for (const RayMatch& m : matches) {
    double y_l, y_r;
    RectifiedRows(om, t, m.left.val, m.right.val, &y_l, &y_r);
    abs_dy.push_back(std::abs(f * (y_r - y_l)));
  }
  const double limit = std::max(kTrimFloorPx, 3 * Quantile(abs_dy, 0.5));
  std::vector<RayMatch> kept;
  for (size_t i = 0; i < matches.size(); ++i)
    if (abs_dy[i] <= limit) kept.push_back(matches[i]);
  return kept;
}

}  // namespace

void RectifiedDyFigures(const Eigen::Matrix3d& R, const Eigen::Vector3d& T, double f,
                        const std::vector<RayMatch>& matches, double* median_abs, double* p95_abs) {
  double om[3];
  AngleAxis(R, om);
  const Eigen::Vector3d t = T.normalized();
  std::vector<double> abs_dy;
  for (const RayMatch& m : matches) {
    double y_l, y_r;
    RectifiedRows(om, t.data(), m.left.val, m.right.val, &y_l, &y_r);
    abs_dy.push_back(std::abs(f * (y_r - y_l)));
  }
  *median_abs = Quantile(abs_dy, 0.5);
  *p95_abs = Quantile(abs_dy, 0.95);
}

RefineResult RefineExtrinsics(const Rig& rig, double f, const std::vector<RayMatch>& matches,
                              cv::Size size, const DyGrid& grid, const RefineOptions& o) {
  RefineResult result;
  result.rig = rig;
  result.matches = int(matches.size());
  RectifiedDyFigures(rig.R, rig.T, f, matches, &result.dy_median_before, &result.dy_p95_before);
  result.refused = Spread(matches, size, grid, o);
  if (!result.refused.empty()) return result;

  double om[3];
  AngleAxis(rig.R, om);
  const Eigen::Vector3d t0 = rig.T.normalized();
  Eigen::Vector3d t = t0;
  std::vector<RayMatch> used = matches;
  for (int round = 0; round < kTrimRounds; ++round) {
    if (!Solve(used, f, o.loss_px, om, t.data(), &result.refused)) return result;
    used = Trimmed(matches, f, om, t.data());
  }
  if (!Solve(used, f, o.loss_px, om, t.data(), &result.refused)) return result;
  result.matches_used = int(used.size());

  Rig refined = rig;
  refined.R = Rotation(om);
  refined.T = rig.T.norm() * t.normalized();
  result.rotation_change_deg = Eigen::AngleAxisd(refined.R * rig.R.transpose()).angle() * kDeg;
  result.translation_direction_change_deg = std::acos(std::clamp(t.normalized().dot(t0), -1.0, 1.0)) * kDeg;
  RectifiedDyFigures(refined.R, refined.T, f, matches, &result.dy_median_after, &result.dy_p95_after);
  if (result.rotation_change_deg > o.max_correction_deg ||
      result.translation_direction_change_deg > o.max_correction_deg) {
    char why[200];
    std::snprintf(why, sizeof why,
                  "the correction (R by %.3f deg, T's direction by %.3f deg) is larger than %.3f deg",
                  result.rotation_change_deg, result.translation_direction_change_deg, o.max_correction_deg);
    result.refused = why;
    return result;
  }
  result.rig = refined;
  result.applied = true;
  return result;
}

}  // namespace ws
