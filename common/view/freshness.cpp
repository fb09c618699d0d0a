#include "view/freshness.h"

#include <algorithm>

#include "lcm_io/channels.h"

namespace ws::view {

void Freshness::Heard(const std::string& channel, int64_t now_us) {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto [it, first] = channels_.try_emplace(channel);
  Clock& clock = it->second;
  if (!first) {
    const double dt = double(std::max<int64_t>(0, now_us - clock.last_us));
    clock.interval_us = clock.interval_us == 0 ? dt : 0.8 * clock.interval_us + 0.2 * dt;
  }
  clock.last_us = now_us;
}

nlohmann::json Freshness::Json(int64_t now_us) const {
  std::lock_guard<std::mutex> lock(mutex_);
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [channel, clock] : channels_) {
    const int64_t silent_us = now_us - clock.last_us;
    const double stale_after_us = std::max(double(kStaleAfterUs), 3 * clock.interval_us);
    out[channel] = {{"source", SourceOf(channel)},
                    {"last_us", clock.last_us},
                    {"age_s", silent_us * 1e-6},
                    {"rate_hz", clock.interval_us > 0 ? nlohmann::json(1e6 / clock.interval_us) : nlohmann::json()},
                    {"stale", silent_us > stale_after_us}};
  }
  return out;
}

std::string Freshness::SourceOf(const std::string& channel) {
  static const std::map<std::string, std::string> sources = {
      {channel::kStereoImages, "stereo-capture"},
      {channel::kStereoCorners, "stereo-detect"},
      {channel::kCalibrationStatus, "stereo-calibrate"},
      {channel::kStereoDisparity, "stereo-match"},
      {channel::kStereoCloudFiltered, "stereo-cloud"},
      {channel::kCloudStats, "stereo-cloud"},
      {channel::kCalibrationHealth, "stereo-health"},
  };
  const auto it = sources.find(channel);
  return it == sources.end() ? "" : it->second;
}

}  // namespace ws::view
