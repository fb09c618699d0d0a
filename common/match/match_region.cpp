#include "match/match_region.h"

#include <algorithm>

namespace ws {

cv::Rect MatchRegion(const Rectification& rect, const MatcherConfig& config) {
  const cv::Rect whole(cv::Point(0, 0), rect.size);
  if (!config.common_field_only || rect.common.empty()) return whole;
  const MatcherReach reach = Reach(config);
  const int n = config.downscale;
  // The corners on multiples of n: the same downscaled grid as the whole image's.
  const auto down = [n](int v) { return std::max(0, v) / n * n; };
  const auto up = [n](int v) { return (v + n - 1) / n * n; };
  const cv::Point top_left(down(rect.common.x - reach.left), down(rect.common.y - reach.rows));
  const cv::Point bottom_right(up(rect.common.br().x + reach.right), up(rect.common.br().y + reach.rows));
  return cv::Rect(top_left, bottom_right) & whole;
}

int ContextColumns(const Rectification& rect, const cv::Rect& region) {
  return rect.common.empty() ? 0 : std::max(0, rect.common.x - region.x);
}

}  // namespace ws
