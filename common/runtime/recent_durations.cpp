#include "runtime/recent_durations.h"

#include <algorithm>
#include <vector>

namespace ws {

void RecentDurations::Add(Duration value) {
  last_.push_back(value);
  if (last_.size() > keep_) last_.pop_front();
}

RecentDurations::Duration RecentDurations::Median() const {
  if (last_.empty()) return Duration::zero();
  std::vector<Duration> sorted(last_.begin(), last_.end());
  std::nth_element(sorted.begin(), sorted.begin() + long(sorted.size() / 2), sorted.end());
  return sorted[sorted.size() / 2];
}

RecentDurations::Duration RecentDurations::Slowest() const {
  return last_.empty() ? Duration::zero() : *std::max_element(last_.begin(), last_.end());
}

RecentDurations::Duration RecentDurations::Fastest() const {
  return last_.empty() ? Duration::zero() : *std::min_element(last_.begin(), last_.end());
}

}  // namespace ws
