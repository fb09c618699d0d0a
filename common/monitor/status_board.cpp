#include "monitor/status_board.h"

#include <cstdarg>
#include <cstdio>
#include <sstream>

namespace ws {
namespace {

std::string Format(const char* fmt, ...) __attribute__((format(printf, 1, 2)));
std::string Format(const char* fmt, ...) {
  char text[512];
  va_list args;
  va_start(args, fmt);
  std::vsnprintf(text, sizeof text, fmt, args);
  va_end(args);
  return text;
}

// Messages per second on a channel between two heartbeats, or -1 if unknown.
double Rate(const widestereo::channel_counters_t& now, const widestereo::process_status_t& latest,
            const std::optional<widestereo::process_status_t>& previous) {
  if (!previous) return -1;
  const double dt = (latest.utime - previous->utime) * 1e-6;
  if (dt <= 0) return -1;
  for (const auto& before : previous->channels)
    if (before.channel == now.channel)
      return ((now.received + now.published) - (before.received + before.published)) / dt;
  return -1;
}

int CoveragePercent(const std::vector<std::vector<int32_t>>& grid) {
  int cells = 0, covered = 0;
  for (const auto& row : grid)
    for (int32_t count : row) {
      ++cells;
      covered += count > 0;
    }
  return cells ? 100 * covered / cells : 0;
}

}  // namespace

void StatusBoard::Add(const widestereo::process_status_t& status) {
  const std::string key = status.name + "@" + status.host + ":" + std::to_string(status.pid);
  auto& entry = processes_[key];
  // Rates are taken over at least half a second: a process's last heartbeat
  // at exit can follow the one before it by microseconds.
  if (entry.latest.utime != 0 && (!entry.previous || status.utime - entry.latest.utime >= 500000))
    entry.previous = entry.latest;
  entry.latest = status;
}

void StatusBoard::Add(const widestereo::calibration_status_t& status) { calibration_ = status; }

void StatusBoard::Add(const widestereo::calibration_health_t& health) { health_ = health; }

std::string StatusBoard::Render() const {
  std::ostringstream out;
  out << Format("%-18s %-12s %7s %9s  %-22s %9s %9s %8s %8s %8s\n", "PROCESS", "STATE", "PID",
                "UPTIME", "CHANNEL", "IN", "OUT", "RATE/s", "DROPPED", "REJECTED");
  for (const auto& [key, entry] : processes_) {
    const auto& s = entry.latest;
    const std::string who = s.name + (s.host.empty() ? "" : "@" + s.host);
    out << Format("%-18.18s %-12.12s %7d %8.0fs\n", who.c_str(), s.state.c_str(), s.pid,
                  s.uptime_s);
    for (const auto& c : s.channels) {
      const double rate = Rate(c, s, entry.previous);
      out << Format("%-18s %-12s %7s %9s  %-22.22s %9lld %9lld %8s %8lld %8lld\n", "", "", "", "",
                    c.channel.c_str(), (long long)c.received, (long long)c.published,
                    rate < 0 ? "-" : Format("%.1f", rate).c_str(), (long long)c.dropped,
                    (long long)c.rejected);
    }
    if (!s.last_error.empty()) out << "    last error: " << s.last_error << "\n";
  }
  if (processes_.empty()) out << "(no PROCESS_STATUS heard yet)\n";
  if (calibration_) {
    const auto& c = *calibration_;
    out << Format("\ncalibration: %s  views left %d right %d stereo %d  coverage left %d%% "
                  "right %d%%  rms %s  held-out %s\n",
                  c.state.c_str(), c.views_left, c.views_right, c.views_stereo,
                  CoveragePercent(c.coverage_left), CoveragePercent(c.coverage_right),
                  c.rms < 0 ? "-" : Format("%.3f px", c.rms).c_str(),
                  c.heldout_rms < 0 ? "-" : Format("%.3f px", c.heldout_rms).c_str());
    if (!c.hint.empty()) out << "hint: " << c.hint << "\n";
  }
  if (health_) {
    const auto& h = *health_;
    out << Format("\nhealth: %-10s median |dy| %s  p95 %s  (max %.2f px; %d matches in %d frames)\n",
                  h.verdict.c_str(), h.dy_median_px < 0 ? "-" : Format("%.3f px", h.dy_median_px).c_str(),
                  h.dy_p95_px < 0 ? "-" : Format("%.3f px", h.dy_p95_px).c_str(), h.max_dy_px, h.matches,
                  h.frames);
  }
  return out.str();
}

}  // namespace ws
