#include "match/downstream_gate.h"

#include <algorithm>
#include <vector>

namespace ws {
namespace {

void Keep(std::deque<DownstreamGate::Clock::duration>* last, DownstreamGate::Clock::duration value) {
  last->push_back(value);
  if (last->size() > size_t(DownstreamGate::kDelays)) last->pop_front();
}

DownstreamGate::Clock::duration Median(const std::deque<DownstreamGate::Clock::duration>& values) {
  if (values.empty()) return DownstreamGate::Clock::duration::zero();
  std::vector<DownstreamGate::Clock::duration> sorted(values.begin(), values.end());
  std::nth_element(sorted.begin(), sorted.begin() + long(sorted.size() / 2), sorted.end());
  return sorted[sorted.size() / 2];
}

}  // namespace

bool DownstreamGate::Open(Clock::time_point now) {
  std::lock_guard<std::mutex> lock(mutex_);
  const Clock::duration slowest = Slowest();
  const Clock::time_point forgotten = now - std::max<Clock::duration>(kMinPatience, 4 * slowest);
  for (auto it = sent_.begin(); it != sent_.end();) it = it->second < forgotten ? sent_.erase(it) : std::next(it);
  if (acknowledged_) {
    const Clock::time_point arrives = now + Median(matchings_);
    const auto held = std::count_if(sent_.begin(), sent_.end(),
                                    [&](const auto& cloud) { return cloud.second + slowest > arrives; });
    if (held >= kInHand) return false;
  }
  opened_ = now;
  return true;
}

void DownstreamGate::Sent(int64_t frame_id, Clock::time_point now) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!sent_.empty() && frame_id <= sent_.rbegin()->first) sent_.clear();
  sent_[frame_id] = now;
  if (opened_) Keep(&matchings_, now - *opened_);
  opened_.reset();
}

void DownstreamGate::Acknowledge(int64_t frame_id, Clock::time_point now) {
  std::lock_guard<std::mutex> lock(mutex_);
  acknowledged_ = true;
  const auto it = sent_.find(frame_id);
  if (it != sent_.end()) Keep(&delays_, now - it->second);
  sent_.erase(sent_.begin(), sent_.upper_bound(frame_id));
}

int DownstreamGate::in_hand() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return int(sent_.size());
}

DownstreamGate::Clock::duration DownstreamGate::Slowest() const {
  return delays_.empty() ? Clock::duration::zero() : *std::max_element(delays_.begin(), delays_.end());
}

}  // namespace ws
