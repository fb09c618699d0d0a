#include "match/downstream_gate.h"

#include <algorithm>

namespace ws {

bool DownstreamGate::TryCommit(int64_t frame_id, Clock::time_point now) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!committed_.empty() && frame_id <= committed_.rbegin()->first) committed_.clear();
  const Clock::time_point given_up = now - Patience();
  for (auto it = committed_.begin(); it != committed_.end();)
    it = it->second < given_up ? committed_.erase(it) : std::next(it);
  if (acknowledged_ && committed_.size() >= size_t(kInHand)) return false;
  committed_[frame_id] = now;
  return true;
}

void DownstreamGate::Acknowledge(int64_t frame_id, Clock::time_point now) {
  std::lock_guard<std::mutex> lock(mutex_);
  acknowledged_ = true;
  const auto it = committed_.find(frame_id);
  if (it != committed_.end()) {
    delays_.push_back(now - it->second);
    if (delays_.size() > size_t(kDelays)) delays_.pop_front();
  }
  committed_.erase(committed_.begin(), committed_.upper_bound(frame_id));
}

int DownstreamGate::in_hand() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return int(committed_.size());
}

DownstreamGate::Clock::duration DownstreamGate::Patience() const {
  Clock::duration slowest = Clock::duration::zero();
  for (const Clock::duration& delay : delays_) slowest = std::max(slowest, delay);
  return std::max<Clock::duration>(kMinPatience, 4 * slowest);
}

}  // namespace ws
