// The live picture of every process on the bus, built from PROCESS_STATUS,
// CALIBRATION_STATUS and CALIBRATION_HEALTH messages, rendered as one screen
// of text (stereo-status).
#pragma once

#include <map>
#include <optional>
#include <string>

#include "widestereo/calibration_health_t.hpp"
#include "widestereo/calibration_status_t.hpp"
#include "widestereo/process_status_t.hpp"

namespace ws {

class StatusBoard {
 public:
  void Add(const widestereo::process_status_t& status);
  void Add(const widestereo::calibration_status_t& status);
  void Add(const widestereo::calibration_health_t& health);
  // The table: one block per process (host, pid, state, uptime, last error)
  // with a row per channel (counts, message rate, drops, rejections), then the
  // calibration state and coverage if a calibrator is running, and the
  // calibration's health (verdict, median |dy|) if stereo-health is.
  std::string Render() const;

 private:
  struct Entry {
    widestereo::process_status_t latest;
    std::optional<widestereo::process_status_t> previous;
  };
  std::map<std::string, Entry> processes_;  // by "name@host:pid"
  std::optional<widestereo::calibration_status_t> calibration_;
  std::optional<widestereo::calibration_health_t> health_;
};

}  // namespace ws
