#include "calib/solver/corner_noise.h"

#include <cmath>
#include <map>
#include <utility>

#include "calib/solver/quality.h"

namespace ws::calib {
namespace {

// The finite difference of order kOrder along a row or column: binomial
// weights of alternating sign; kSumOfSquares their sum of squares.
constexpr int kOrder = 3;
constexpr double kWeights[kOrder + 1] = {-1, 3, -3, 1};
constexpr double kSumOfSquares = 20;

// The smallest distance between two corners' board points (the grid's
// spacing); 0 when there are fewer than two distinct points.
double GridSpacing(const BoardView& view) {
  double spacing = 0;
  for (int i = 0; i < view.size(); ++i)
    for (int j = i + 1; j < view.size(); ++j) {
      const double d = (view.object[i] - view.object[j]).norm();
      if (d > 0 && (spacing == 0 || d < spacing)) spacing = d;
    }
  return spacing;
}

}  // namespace

double CornerNoise(const BoardView& view) {
  const double h = GridSpacing(view);
  if (h <= 0) return 0;
  // Each corner at its (column, row) on the board's grid.
  std::map<std::pair<long, long>, int> at;
  auto cell = [&](int i) {
    return std::make_pair(std::lround(view.object[i].x() / h), std::lround(view.object[i].y() / h));
  };
  for (int i = 0; i < view.size(); ++i) at[cell(i)] = i;
  std::vector<double> norms;
  for (int i = 0; i < view.size(); ++i) {
    const auto [c, r] = cell(i);
    for (const auto& [dc, dr] : {std::make_pair(1L, 0L), std::make_pair(0L, 1L)}) {
      Eigen::Vector2d e = Eigen::Vector2d::Zero();
      bool complete = true;
      for (int k = 0; k < kOrder + 1 && complete; ++k) {
        const auto corner = at.find({c + k * dc, r + k * dr});
        complete = corner != at.end();
        if (complete) e += kWeights[k] * view.image[corner->second];
      }
      if (complete) norms.push_back(e.norm());
    }
  }
  if (norms.empty()) return 0;
  return Median(std::move(norms)) / (std::sqrt(kSumOfSquares) * std::sqrt(2.0 * std::log(2.0)));
}

double MedianCornerNoise(const std::vector<const BoardView*>& views) {
  std::vector<double> noise;
  for (const BoardView* view : views) noise.push_back(CornerNoise(*view));
  return noise.empty() ? 0.0 : Median(std::move(noise));
}

}  // namespace ws::calib
