// A bound on the latency from a frame's capture to the end of the chain's
// work on it, so that a chain that cannot keep up (a slower minute of the
// machine, another process on its cores) drops whole frames early instead of
// delivering every frame later: a stage about to start on a frame asks
// whether the frame's age now (from its utime, the capture's wall-clock
// stamp) plus what the rest of the chain takes from there (the median of its
// last runs, RecentDurations) would exceed the budget, and if so skips it
// before spending work on it, counted as skipped with kSkipReason
// (Process::CountSkipped). The median, not the slowest, so that only a frame
// already late by the usual pace is dropped: a chain that keeps up drops
// none.
//
// A frame is skipped only while a fresher one could make it: while the
// youngest of the last kAges frames offered, plus the rest, is within the
// budget. A frame comes to the stage no younger than its transport and the
// stages before allow; where even that age plus the rest exceeds the budget
// (a machine too slow for it), skipping would deliver nothing at all, and
// every frame comes late instead. A skipped frame leaves the stage free, so
// the next comes about as young as the youngest: skipping cannot starve it.
//
// The ages need stamps on this host's wall clock (stereo-capture's own, or
// an Aravis camera's host timestamp); a stamp more than kClockMismatch away
// from it (a --frame-clock stream, a log's times) is not taken for an age:
// such a frame is never late.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>

#include "runtime/recent_durations.h"

namespace ws {

class LatencyBudget {
 public:
  static constexpr const char* kSkipReason = "it would come later than the latency budget";
  static constexpr std::chrono::seconds kClockMismatch{60};
  static constexpr size_t kAges = 16;

  // budget_ms 0: no bound.
  explicit LatencyBudget(double budget_ms = 0) : budget_(std::chrono::microseconds(int64_t(budget_ms * 1000))) {}
  bool bounded() const { return budget_.count() > 0; }
  // True when a frame stamped `utime`, whose remaining work starts at
  // `now_utime` (both microseconds of the wall clock) and takes `rest`, would
  // be done later than the budget allows while a fresher one would not.
  // Not thread-safe: one stage's, called once per frame it is offered.
  bool Late(int64_t utime, int64_t now_utime, RecentDurations::Duration rest);

 private:
  std::chrono::microseconds budget_;
  RecentDurations ages_{kAges};  // of the last frames offered
};

}  // namespace ws
