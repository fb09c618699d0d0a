#include "view/board_spread.h"

#include <algorithm>
#include <cmath>

namespace ws::view {
namespace {

// Twice the area of the quadrilateral a b c d (its diagonals' cross product).
double QuadArea(const double* a, const double* b, const double* c, const double* d) {
  const double p[2] = {c[0] - a[0], c[1] - a[1]}, q[2] = {d[0] - b[0], d[1] - b[1]};
  return std::abs(p[0] * q[1] - p[1] * q[0]) / 2;
}

}  // namespace

std::optional<BoardMeasures> MeasureBoard(const widestereo::camera_corners_t& corners) {
  const int n = std::min<int>(corners.n, int(std::min(corners.image_points.size(), corners.object_points.size())));
  if (n < 4 || corners.image_width <= 0 || corners.image_height <= 0) return std::nullopt;
  // The board's extent in its own plane.
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < 2; ++k) {
      lo[k] = std::min(lo[k], corners.object_points[i][k]);
      hi[k] = std::max(hi[k], corners.object_points[i][k]);
    }
  // Its outline: up-left, up-right, down-right, down-left.
  const double targets[4][2] = {{lo[0], lo[1]}, {hi[0], lo[1]}, {hi[0], hi[1]}, {lo[0], hi[1]}};
  const double* outline[4];
  for (int t = 0; t < 4; ++t) {
    int best = 0;
    double best_d = INFINITY;
    for (int i = 0; i < n; ++i) {
      const double d =
          std::hypot(corners.object_points[i][0] - targets[t][0], corners.object_points[i][1] - targets[t][1]);
      if (d < best_d) best_d = d, best = i;
    }
    outline[t] = corners.image_points[best].data();
  }
  const double area = QuadArea(outline[0], outline[1], outline[2], outline[3]);
  if (!(area > 0)) return std::nullopt;
  double mean[2] = {0, 0};
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < 2; ++k) mean[k] += corners.image_points[i][k] / n;
  const double w = corners.image_width, h = corners.image_height, border = std::sqrt(area);
  auto across = [border](double centre, double extent) {
    return extent > border ? std::clamp((centre - border / 2) / (extent - border), 0.0, 1.0) : 0.5;
  };
  const double a[2] = {outline[1][0] - outline[0][0], outline[1][1] - outline[0][1]};
  const double b[2] = {outline[2][0] - outline[1][0], outline[2][1] - outline[1][1]};
  const double cosine = (a[0] * b[0] + a[1] * b[1]) / std::max(1e-12, std::hypot(a[0], a[1]) * std::hypot(b[0], b[1]));
  const double angle = std::acos(std::clamp(cosine, -1.0, 1.0));
  return BoardMeasures{across(mean[0], w), across(mean[1], h), std::sqrt(area / (w * h)),
                       std::min(1.0, 2 * std::abs(M_PI / 2 - angle))};
}

bool BoardSpread::Add(const BoardMeasures& m) {
  if (kept_.size() >= kMaxBoards) return false;
  for (const BoardMeasures& k : kept_) {
    double distance = 0;
    for (size_t i = 0; i < m.size(); ++i) distance += std::abs(m[i] - k[i]);
    if (distance <= 0.2) return false;
  }
  kept_.push_back(m);
  return true;
}

std::array<std::pair<double, double>, 4> BoardSpread::Ranges() const {
  std::array<std::pair<double, double>, 4> ranges;
  ranges.fill({INFINITY, -INFINITY});
  for (const BoardMeasures& k : kept_)
    for (size_t i = 0; i < k.size(); ++i)
      ranges[i] = {std::min(ranges[i].first, k[i]), std::max(ranges[i].second, k[i])};
  return ranges;
}

std::array<double, 4> BoardSpread::Progress() const {
  std::array<double, 4> progress{};
  if (kept_.empty()) return progress;
  const auto ranges = Ranges();
  for (size_t i = 0; i < progress.size(); ++i)
    progress[i] = std::min(1.0, (ranges[i].second - ranges[i].first) / kWantedRange[i]);
  return progress;
}

bool BoardSpread::Enough() const {
  const auto progress = Progress();
  return int(kept_.size()) >= kEnoughBoards ||
         (!kept_.empty() && std::all_of(progress.begin(), progress.end(), [](double p) { return p >= 1; }));
}

nlohmann::json BoardSpread::Json() const {
  static const char* names[] = {"x", "y", "size", "skew"};
  const auto progress = Progress();
  const auto ranges = Ranges();
  const auto figure = [this](double v) { return kept_.empty() ? nlohmann::json() : nlohmann::json(v); };
  nlohmann::json bars = nlohmann::json::array();
  for (size_t i = 0; i < progress.size(); ++i)
    bars.push_back({{"name", names[i]},
                    {"low", figure(ranges[i].first)},
                    {"high", figure(ranges[i].second)},
                    {"progress", progress[i]}});
  return {{"boards", kept_.size()}, {"bars", bars}, {"enough", Enough()}};
}

}  // namespace ws::view
