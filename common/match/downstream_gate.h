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
// The gate closes while kInHand clouds sent (or matched and on their way:
// stereo-match's publishing stage runs beside its matching) are not
// acknowledged: one being filtered and one waiting, so that the cloud of a
// pair matched now would replace the waiting one unless the filter
// finished first. It stays open
// until the first acknowledgement (no filter is known to be there:
// stereo-match alone, or read by stereo-view only). A cloud not acknowledged
// within the patience is given up on (the filter stopped, or its
// acknowledgement was lost): 4 times the slowest of the last kDelays
// acknowledgements, so that it follows the machine's speed, and never less
// than kMinPatience, two of the filter's heartbeat periods.
#pragma once

#include <chrono>
#include <cstdint>
#include <deque>
#include <map>
#include <mutex>

namespace ws {

class DownstreamGate {
 public:
  using Clock = std::chrono::steady_clock;
  static constexpr int kInHand = 2;
  static constexpr int kDelays = 16;
  static constexpr std::chrono::milliseconds kMinPatience{2000};

  // True when a pair may be matched now.
  bool Open(Clock::time_point now);
  // A cloud sent to the filter, or matched and to be sent. A frame id below
  // one in hand (the capture restarted) forgets those.
  void Sent(int64_t frame_id, Clock::time_point now);
  // The filter's CLOUD_STATS for `frame_id`: it and every cloud before it
  // are settled.
  void Acknowledge(int64_t frame_id, Clock::time_point now);
  // Sent and not acknowledged, as of the last call.
  int in_hand() const;

 private:
  Clock::duration Patience() const;

  mutable std::mutex mutex_;
  std::map<int64_t, Clock::time_point> sent_;  // frame id -> when
  std::deque<Clock::duration> delays_;         // the last acknowledgements'
  bool acknowledged_ = false;                  // a filter is there
};

}  // namespace ws
