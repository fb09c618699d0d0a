// Flow control between stereo-match and the cloud filter after it
// (stereo-cloud), so that a pair the chain cannot carry is skipped whole,
// before it is matched, and not half-way: stereo-cloud keeps only the newest
// cloud waiting (runtime/newest_first.h), so a cloud that comes while one is
// filtered and another waits replaces that one, and the matching spent on it
// is lost. stereo-cloud acknowledges every cloud it filters with its
// CLOUD_STATS (the same frame_id); it takes clouds in frame order, so an
// acknowledgement also settles every earlier cloud (filtered, replaced or
// lost on the way).
//
// A pair is skipped when, by the time its cloud would be sent, the filter
// would still hold kInHand clouds (one being filtered, one waiting): a cloud
// sent (or matched and on its way: stereo-match's publishing stage runs
// beside its matching) counts as held until the slowest of the last kDelays
// acknowledgements has passed since it was sent, and the pair's cloud would
// be sent the median of the last kDelays matchings (Open to Sent) from now.
// So a matcher slower than the filter is never held back, and one faster
// is held to the filter's pace. The gate stays open until the first
// acknowledgement (no filter is known to be there: stereo-match alone, or
// read by stereo-view only). A cloud never acknowledged (the filter stopped,
// or lost it) is forgotten after 4 times the slowest acknowledgement, at
// least kMinPatience, two of the filter's heartbeat periods.
#pragma once

#include <chrono>
#include <cstdint>
#include <map>
#include <mutex>
#include <optional>

#include "runtime/recent_durations.h"

namespace ws {

class DownstreamGate {
 public:
  using Clock = std::chrono::steady_clock;
  static constexpr int kInHand = 2;
  static constexpr int kDelays = 16;
  static constexpr std::chrono::milliseconds kMinPatience{2000};

  // True when a pair may be matched now (its matching starts).
  bool Open(Clock::time_point now);
  // The cloud of a pair matched, to be sent to the filter. A frame id below
  // one in hand (the capture restarted) forgets those.
  void Sent(int64_t frame_id, Clock::time_point now);
  // The filter's CLOUD_STATS for `frame_id`: it and every cloud before it
  // are settled.
  void Acknowledge(int64_t frame_id, Clock::time_point now);
  // Sent and neither acknowledged nor forgotten, as of the last call.
  int in_hand() const;
  // What a pair whose matching starts now takes until the filter
  // acknowledges its cloud: the median matching (Open to Sent) plus the
  // median acknowledgement (Sent to Acknowledge), the latter zero until a
  // filter has acknowledged one (runtime/latency_budget.h).
  Clock::duration ToAcknowledgement() const;

 private:
  mutable std::mutex mutex_;
  std::map<int64_t, Clock::time_point> sent_;  // frame id -> when
  RecentDurations delays_{kDelays};            // the last acknowledgements' (Sent to Acknowledge)
  RecentDurations matchings_{kDelays};         // the last matchings' (Open to Sent)
  std::optional<Clock::time_point> opened_;    // the matching under way's start
  bool acknowledged_ = false;                  // a filter is there
};

}  // namespace ws
