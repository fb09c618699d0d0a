// The live picture of every process on the bus, built from PROCESS_STATUS,
// CALIBRATION_STATUS, CALIBRATION_HEALTH and CLOUD_STATS messages, rendered
// as one screen of text (stereo-status).
//
// It stays true: a process whose heartbeats stopped (killed, its host gone)
// is shown as gone after kGoneAfterUs, one that ended says so from its last
// heartbeat ("exited": its work done, "stopped": by a signal, "failed"); names are never cut; frames skipped for a
// newer one (the newest-frame policy) are shown apart from frames lost; and
// the table fits the screen it is given, condensing before it cuts.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "widestereo/calibration_health_t.hpp"
#include "widestereo/calibration_status_t.hpp"
#include "widestereo/cloud_stats_t.hpp"
#include "widestereo/process_status_t.hpp"

namespace ws {

// Three heartbeat periods without one: the process is gone.
inline constexpr int64_t kGoneAfterUs = 3000000;

struct Screen {
  int cols = 0, rows = 0;  // 0: no limit
};

class StatusBoard {
 public:
  // One process as the tables show it (stereo-status's text, the page's HTML).
  struct ChannelRow {
    std::string channel;
    int64_t in = 0, out = 0, lost = 0, skipped = 0, rejected = 0;
    double rate = -1;  // messages per second; < 0: unknown
  };
  struct ProcessRow {
    std::string who, state, uptime;  // state: "gone" once silent kGoneAfterUs
    int pid = 0;
    bool ended = false;  // its last heartbeat said so: exited, stopped or failed
    bool gone = false;
    std::vector<ChannelRow> channels;
    std::vector<std::string> stages;  // "STAGE median/p99" (ms), while not gone
    std::string last_error;
  };

  // Each message with the time it was received (microseconds, the board's
  // own clock: the senders' clocks need not agree with it).
  void Add(const widestereo::process_status_t& status, int64_t received_us);
  void Add(const widestereo::calibration_status_t& status);
  void Add(const widestereo::calibration_health_t& health);
  void Add(const widestereo::cloud_stats_t& stats, int64_t received_us);
  // The table at `now_us`: one block per process (host, pid, state, uptime,
  // last error) with a row per channel (counts, message rate, losses, skips,
  // rejections) and its latency budget (each stage's time per frame, median
  // and p99), then the depth, calibration and health lines, within `screen`.
  std::string Render(int64_t now_us, Screen screen = {}) const;
  // Every process heard within the last kForgetAfterUs, by name.
  std::vector<ProcessRow> Rows(int64_t now_us) const;

 private:
  struct Entry {
    widestereo::process_status_t latest;
    std::optional<widestereo::process_status_t> previous;
    int64_t heard_us = 0;
  };
  struct Depth {
    widestereo::cloud_stats_t latest;
    int64_t first_us = 0, heard_us = 0;
    int64_t clouds = 0;
  };
  // The table's lines; `condensed`: no channel rows or budgets, only the
  // processes' totals; lines broken to `cols` where they can be (0: never).
  std::vector<std::string> ProcessLines(int64_t now_us, bool condensed, int cols) const;
  std::vector<std::string> SummaryLines(int64_t now_us, int cols) const;

  std::map<std::string, Entry> processes_;  // by "name@host:pid"
  std::optional<widestereo::calibration_status_t> calibration_;
  std::optional<widestereo::calibration_health_t> health_;
  std::optional<Depth> depth_;
};

}  // namespace ws
