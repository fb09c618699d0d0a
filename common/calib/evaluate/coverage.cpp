#include "calib/evaluate/coverage.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace ws::calib {

CoverageGrid::CoverageGrid(int rows_, int cols_) : rows(rows_), cols(cols_) {
  count.assign(std::max(0, rows * cols), 0);
}

void CoverageGrid::Add(const BoardView& view, int width, int height) {
  if (count.size() != size_t(std::max(0, rows * cols))) count.assign(std::max(0, rows * cols), 0);
  if (width > 0 && height > 0) {
    image_width = width;
    image_height = height;
  }
  if (image_width <= 0 || image_height <= 0) return;
  for (const auto& p : view.image) {
    // Only corners inside the image count; the test is on the doubles, before
    // any conversion to int (a corner at 1e244 px: a fuzz finding).
    const double x = std::floor((p.x() + 0.5) * cols / image_width);
    const double y = std::floor((p.y() + 0.5) * rows / image_height);
    if (!(x >= 0 && x < cols && y >= 0 && y < rows)) continue;
    ++count[static_cast<int>(y) * cols + static_cast<int>(x)];
  }
}

std::vector<std::string> CoverageGrid::EmptyRegions() const {
  // Region index 0..8 (row-major 3 x 3) of each cell; a region is empty when
  // at least half of its cells are.
  static const char* kNames[9] = {"top-left corner",    "top edge",    "top-right corner",
                                  "left edge",          "centre",      "right edge",
                                  "bottom-left corner", "bottom edge", "bottom-right corner"};
  auto band = [](int i, int n) { return i == 0 ? 0 : i == n - 1 ? 2 : 1; };
  int cells[9] = {}, empty[9] = {};
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      const int region = 3 * band(r, rows) + band(c, cols);
      ++cells[region];
      if (count.empty() || count[r * cols + c] == 0) ++empty[region];
    }
  std::vector<std::string> out;
  // Corners first, then edges, then the centre: the periphery matters most.
  for (int region : {0, 2, 6, 8, 1, 3, 5, 7, 4})
    if (cells[region] > 0 && 2 * empty[region] >= cells[region]) out.push_back(kNames[region]);
  return out;
}

namespace {

std::string List(const std::vector<std::string>& items) {
  std::string out;
  for (size_t i = 0; i < items.size(); ++i)
    out += (i == 0 ? "" : i + 1 == items.size() ? " and " : ", ") + items[i];
  return out;
}

}  // namespace

std::string CoverageHint(const CoverageStatus& s, int min_views) {
  std::vector<std::string> parts;
  if (s.views_left < min_views || s.views_right < min_views)
    parts.push_back("need at least " + std::to_string(min_views) + " views per camera (left " +
                    std::to_string(s.views_left) + ", right " + std::to_string(s.views_right) +
                    "): show the board tilted in different directions");
  else if (s.views_stereo < min_views)
    parts.push_back("need the board seen by both cameras at once (" +
                    std::to_string(s.views_stereo) + " stereo views, " + std::to_string(min_views) +
                    " needed)");
  for (const auto* side : {"left", "right"}) {
    const CoverageGrid& grid = std::string(side) == "left" ? s.left : s.right;
    const auto empty = grid.EmptyRegions();
    if (!empty.empty())
      parts.push_back("move the board into the " + List(empty) + " of the " + side + " image");
  }
  if (parts.empty())
    return "coverage complete (" + std::to_string(s.views_stereo) +
           " stereo views): add tilted views at the edges, or send 'solve'";
  std::string hint;
  for (const auto& p : parts) hint += (hint.empty() ? "" : "; ") + p;
  return hint;
}

bool NearDuplicate(const BoardView& candidate, const BoardView& existing, double threshold_px) {
  if (candidate.empty() || existing.empty()) return candidate.empty() && existing.empty();
  std::map<int, int> index;
  for (int i = 0; i < existing.size(); ++i) index[existing.ids[i]] = i;
  int common = 0;
  double distance = 0;
  for (int i = 0; i < candidate.size(); ++i) {
    const auto it = index.find(candidate.ids[i]);
    if (it == index.end()) continue;
    ++common;
    distance += (candidate.image[i] - existing.image[it->second]).norm();
  }
  const int most = std::max(candidate.size(), existing.size());
  if (common < 0.8 * most || common == 0) return false;
  return distance / common <= threshold_px;
}

}  // namespace ws::calib
