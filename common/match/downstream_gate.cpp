#include "match/downstream_gate.h"

#include <algorithm>

namespace ws {

bool DownstreamGate::Open(Clock::time_point now) {
  std::lock_guard<std::mutex> lock(mutex_);
  const Clock::duration slowest = delays_.Slowest();
  const Clock::time_point forgotten = now - std::max<Clock::duration>(kMinPatience, 4 * slowest);
  for (auto it = sent_.begin(); it != sent_.end();) it = it->second < forgotten ? sent_.erase(it) : std::next(it);
  if (acknowledged_) {
    const Clock::time_point arrives = now + matchings_.Median();
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
  if (opened_) matchings_.Add(now - *opened_);
  opened_.reset();
}

void DownstreamGate::Acknowledge(int64_t frame_id, Clock::time_point now) {
  std::lock_guard<std::mutex> lock(mutex_);
  acknowledged_ = true;
  const auto it = sent_.find(frame_id);
  if (it != sent_.end()) delays_.Add(now - it->second);
  sent_.erase(sent_.begin(), sent_.upper_bound(frame_id));
}

int DownstreamGate::in_hand() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return int(sent_.size());
}

DownstreamGate::Clock::duration DownstreamGate::ToAcknowledgement() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return matchings_.Median() + delays_.Median();
}

}  // namespace ws
