#include "calib/pair_consistency.h"

#include <algorithm>
#include <cmath>

#include "calib/solver/quality.h"

namespace ws::calib {
namespace {

constexpr double kChiSquare6Median = 5.35;
constexpr double kChiSquare6Quantile = 39.49;  // 5 sigma: 1 - 5.7e-7
constexpr double kNormalQuantile = 5.0;

// Per view, the inlier corners' squared residuals over sigma2.
std::vector<double> ViewCost(const std::vector<CornerResidual>& residuals, int n, double sigma2) {
  std::vector<double> cost(n, 0.0);
  for (const auto& r : residuals)
    if (!r.outlier) cost[r.view] += r.residual.squaredNorm() / sigma2;
  return cost;
}

// The rise per view of camera c's cost in `problem` over its own solve.
std::vector<double> Rise(const Problem& problem, int c, const MonoState& mono, int n) {
  const std::vector<CornerResidual> alone = Residuals(mono.problem, 0);
  const double sigma2 = std::max(std::pow(Rms(alone), 2) / 2, 1e-12);  // per coordinate
  const auto cost_alone = ViewCost(alone, n, sigma2);
  auto cost = ViewCost(Residuals(problem, c), n, sigma2);
  for (int v = 0; v < n; ++v) cost[v] -= cost_alone[v];
  return cost;
}

}  // namespace

PairConsistency CheckPairs(const Problem& through_rig, const MonoState (&mono)[2],
                           const std::vector<bool>& is_stereo) {
  const int n = static_cast<int>(is_stereo.size());
  PairConsistency out;
  out.rise.assign(n, 0.0);
  std::vector<double> rises;
  for (int c = 0; c < 2; ++c) {
    const auto rise = Rise(through_rig, c, mono[c], n);
    for (int v = 0; v < n; ++v)
      if (is_stereo[v]) out.rise[v] += rise[v];
  }
  for (int v = 0; v < n; ++v)
    if (is_stereo[v]) rises.push_back(out.rise[v]);
  if (rises.empty()) return out;
  out.inflation = std::max(1.0, Median(rises) / kChiSquare6Median);
  for (int v = 0; v < n; ++v)
    if (is_stereo[v] && out.rise[v] > out.inflation * kChiSquare6Quantile)
      out.inconsistent.push_back(v);
  return out;
}

bool JointFitsAsWellAsAlone(const Problem& joint, const MonoState (&mono)[2], int pairs) {
  const int n = static_cast<int>(mono[0].prepared.views.size());
  double total = 0;
  for (int c = 0; c < 2; ++c)
    for (double rise : Rise(joint, c, mono[c], n)) total += rise;
  const double dof = 6.0 * pairs;
  return total <= dof + kNormalQuantile * std::sqrt(2 * dof);
}

}  // namespace ws::calib
