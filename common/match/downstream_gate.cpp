#include "match/downstream_gate.h"

#include <algorithm>

namespace ws {

bool DownstreamGate::Open(Clock::time_point now) {
  std::lock_guard<std::mutex> lock(mutex_);
  const Clock::time_point given_up = now - Patience();
  for (auto it = sent_.begin(); it != sent_.end();) it = it->second < given_up ? sent_.erase(it) : std::next(it);
  return !acknowledged_ || sent_.size() < size_t(kInHand);
}

void DownstreamGate::Sent(int64_t frame_id, Clock::time_point now) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!sent_.empty() && frame_id <= sent_.rbegin()->first) sent_.clear();
  sent_[frame_id] = now;
}

void DownstreamGate::Acknowledge(int64_t frame_id, Clock::time_point now) {
  std::lock_guard<std::mutex> lock(mutex_);
  acknowledged_ = true;
  const auto it = sent_.find(frame_id);
  if (it != sent_.end()) {
    delays_.push_back(now - it->second);
    if (delays_.size() > size_t(kDelays)) delays_.pop_front();
  }
  sent_.erase(sent_.begin(), sent_.upper_bound(frame_id));
}

int DownstreamGate::in_hand() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return int(sent_.size());
}

DownstreamGate::Clock::duration DownstreamGate::Patience() const {
  Clock::duration slowest = Clock::duration::zero();
  for (const Clock::duration& delay : delays_) slowest = std::max(slowest, delay);
  return std::max<Clock::duration>(kMinPatience, 4 * slowest);
}

}  // namespace ws
