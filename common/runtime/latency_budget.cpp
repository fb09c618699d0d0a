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

void AddLatencyBudgetOption(CLI::App& app, double& budget_ms, const std::string& stage, const std::string& rest) {
  app.add_option("--latency-budget", budget_ms,
                 "Live, milliseconds from a frame's capture stamp (this host's clock) to " + rest +
                     ": before " + stage + ", a frame whose age plus the median time of that rest would exceed "
                     "it is skipped whole and counted as skipped, so that a chain that cannot keep up drops "
                     "frames early instead of delivering each one later (0: no bound)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
}

}  // namespace ws
