// How fresh what the page shows is: when stereo-view last heard each channel
// it reads, from which process, at what rate, and whether the channel has
// gone stale (silent longer than kStaleAfterUs, or than three of its own
// recent intervals when it is slower than that). A channel never heard is
// not stale: its panel says what it waits for. Thread-safe.
#pragma once

#include <cstdint>
#include <map>
#include <mutex>
#include <string>

#include <nlohmann/json.hpp>

namespace ws::view {

class Freshness {
 public:
  static constexpr int64_t kStaleAfterUs = 3000000;

  // A message on `channel` arrived at `now_us` (stereo-view's clock).
  void Heard(const std::string& channel, int64_t now_us);
  // Every channel heard: {"CHANNEL": {"source": PROCESS, "last_us": T,
  // "age_s": A, "rate_hz": R (null until two came), "stale": B}}.
  nlohmann::json Json(int64_t now_us) const;
  // The process that publishes `channel` (docs: DESIGN.md's table), or "".
  static std::string SourceOf(const std::string& channel);

 private:
  struct Clock {
    int64_t last_us = 0;
    double interval_us = 0;  // recent mean between two messages; 0 until two came
  };
  mutable std::mutex mutex_;
  std::map<std::string, Clock> channels_;
};

}  // namespace ws::view
