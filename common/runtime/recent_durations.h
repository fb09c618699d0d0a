// The last few durations of a recurring piece of work (a matching, a
// filter's run, an acknowledgement's delay), and their median and slowest:
// what the next one is likely to take, from what the machine does now rather
// than from a constant. Not thread-safe: its owner guards it.
#pragma once

#include <chrono>
#include <cstddef>
#include <deque>

namespace ws {

class RecentDurations {
 public:
  using Duration = std::chrono::steady_clock::duration;

  explicit RecentDurations(size_t keep) : keep_(keep) {}
  // Keeps `value`, forgetting the oldest beyond `keep`.
  void Add(Duration value);
  // Zero while none is kept.
  Duration Median() const;
  Duration Slowest() const;
  Duration Fastest() const;
  bool empty() const { return last_.empty(); }

 private:
  size_t keep_;
  std::deque<Duration> last_;
};

}  // namespace ws
