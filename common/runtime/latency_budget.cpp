#include "runtime/latency_budget.h"

namespace ws {

bool LatencyBudget::Late(int64_t utime, int64_t now_utime, RecentDurations::Duration rest) {
  if (!bounded()) return false;
  const std::chrono::microseconds age(now_utime - utime);
  if (age > kClockMismatch || age < -kClockMismatch) return false;  // not this host's clock
  ages_.Add(age);
  const auto rest_us = std::chrono::duration_cast<std::chrono::microseconds>(rest);
  const auto youngest = std::chrono::duration_cast<std::chrono::microseconds>(ages_.Fastest());
  return youngest + rest_us <= budget_ && age + rest_us > budget_;
}

}  // namespace ws
