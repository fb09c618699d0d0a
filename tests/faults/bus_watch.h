// The test's own end of a udpm bus: it publishes raw payloads, and keeps the
// heartbeats of one process and the payloads published on chosen channels.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <lcm/lcm-cpp.hpp>

#include "widestereo/process_status_t.hpp"
#include "widestereo/stereo_calibration_t.hpp"

namespace ws::test {

class BusWatch {
 public:
  // Listens on `url` to the heartbeats of the process named `process`.
  BusWatch(const std::string& url, std::string process);

  void Collect(const std::string& channel);
  void Publish(const std::string& channel, const std::vector<uint8_t>& payload);
  template <class Msg>
  void Publish(const std::string& channel, const Msg& msg) {
    lcm_.publish(channel, &msg);
  }

  // Handles messages until `done` holds or `seconds` have passed; returns done().
  bool ListenUntil(double seconds, const std::function<bool()>& done);
  // Handles messages for `seconds`.
  void Listen(double seconds) { ListenUntil(seconds, [] { return false; }); }

  // The latest heartbeat, if any, and its counters of `channel` (zeros if none).
  const std::optional<widestereo::process_status_t>& status() const { return status_; }
  widestereo::channel_counters_t Counters(const std::string& channel) const;
  const std::vector<std::vector<uint8_t>>& Payloads(const std::string& channel) {
    return payloads_[channel];
  }
  // The payloads kept on `channel` so far, forgotten here.
  std::vector<std::vector<uint8_t>> TakePayloads(const std::string& channel) {
    return std::exchange(payloads_[channel], {});
  }

 private:
  lcm::LCM lcm_;
  std::string process_;
  std::optional<widestereo::process_status_t> status_;
  std::map<std::string, std::vector<std::vector<uint8_t>>> payloads_;
};

// Waits for the watched process's first heartbeat, publishes `calibration`
// and waits until the process says "matching"; false when either takes
// longer than `seconds`.
bool StartMatching(BusWatch& bus, const widestereo::stereo_calibration_t& calibration, double seconds = 20);

}  // namespace ws::test
