#include "monitor/status_board.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <sstream>
#include <vector>

namespace ws {
namespace {

// A process gone this long leaves the table.
constexpr int64_t kForgetAfterUs = 300000000;

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

std::string Who(const widestereo::process_status_t& s) { return s.name + (s.host.empty() ? "" : "@" + s.host); }

// `items` after `prefix`, each whole, a space between two, in lines of at
// most `cols` (an item longer than that alone on its line).
std::vector<std::string> Packed(const std::string& prefix, const std::vector<std::string>& items, int cols) {
  std::vector<std::string> lines;
  std::string line = prefix;
  bool empty = true;
  for (const std::string& item : items) {
    if (!empty && cols > 0 && int(line.size() + 1 + item.size()) > cols) {
      lines.push_back(line);
      line = std::string(prefix.size(), ' ');
      empty = true;
    }
    line += (empty ? "" : " ") + item;
    empty = false;
  }
  lines.push_back(line);
  return lines;
}

// `text` after `prefix`, broken between words into lines of at most `cols`.
std::vector<std::string> Wrapped(const std::string& prefix, const std::string& text, int cols) {
  std::vector<std::string> words;
  std::istringstream in(text);
  for (std::string word; in >> word;) words.push_back(word);
  return Packed(prefix, words, cols);
}

// A process's latency budget: each stage's time per frame, median / p99.
std::vector<std::string> StageLines(const StatusBoard::ProcessRow& row, int cols) {
  std::vector<std::string> items;
  for (size_t i = 0; i < row.stages.size(); ++i)
    items.push_back(row.stages[i] + (i + 1 < row.stages.size() ? "," : ""));
  return Packed("    ms median/p99: ", items, cols);
}

}  // namespace

void StatusBoard::Add(const widestereo::process_status_t& status, int64_t received_us) {
  const std::string key = status.name + "@" + status.host + ":" + std::to_string(status.pid);
  auto& entry = processes_[key];
  // Rates are taken over at least half a second: a process's last heartbeat
  // at exit can follow the one before it by microseconds.
  if (entry.latest.utime != 0 && (!entry.previous || status.utime - entry.latest.utime >= 500000))
    entry.previous = entry.latest;
  entry.latest = status;
  entry.heard_us = received_us;
}

void StatusBoard::Add(const widestereo::calibration_status_t& status) { calibration_ = status; }

void StatusBoard::Add(const widestereo::calibration_health_t& health) { health_ = health; }

void StatusBoard::Add(const widestereo::cloud_stats_t& stats, int64_t received_us) {
  if (!depth_) depth_ = Depth{stats, received_us, received_us, 0};
  depth_->latest = stats;
  depth_->heard_us = received_us;
  ++depth_->clouds;
}

std::vector<StatusBoard::ProcessRow> StatusBoard::Rows(int64_t now_us) const {
  std::vector<ProcessRow> rows;
  for (const auto& [key, entry] : processes_) {
    const auto& s = entry.latest;
    const int64_t silent_us = now_us - entry.heard_us;
    if (silent_us > kForgetAfterUs) continue;
    ProcessRow row;
    row.who = Who(s);
    row.pid = s.pid;
    row.gone = silent_us > kGoneAfterUs;
    row.ended = s.state == "exited" || s.state == "stopped" || s.state == "failed";
    row.state = row.gone && !row.ended ? "gone" : s.state;
    row.uptime = !row.gone ? Format("%.0fs", s.uptime_s)
                 : Format(row.ended ? "ended %llds ago" : "gone %llds", (long long)(silent_us / 1000000));
    for (const auto& c : s.channels)
      row.channels.push_back({c.channel, c.received, c.published, c.dropped, c.skipped, c.rejected,
                              row.gone ? -1 : Rate(c, s, entry.previous)});
    if (!row.gone)
      for (const auto& t : s.stages) row.stages.push_back(t.stage + Format(" %.1f/%.1f", t.median_ms, t.p99_ms));
    row.last_error = s.last_error;
    rows.push_back(std::move(row));
  }
  return rows;
}

std::vector<std::string> StatusBoard::ProcessLines(int64_t now_us, bool condensed, int cols) const {
  const std::vector<ProcessRow> rows = Rows(now_us);
  size_t width = 7;  // "PROCESS"
  for (const auto& row : rows) width = std::max(width, row.who.size());
  const int w = int(width);
  std::vector<std::string> lines;
  lines.push_back(condensed ? Format("%-*s %-14s %7s %8s  %s", w, "PROCESS", "STATE", "PID", "UPTIME",
                                     "IN / OUT / LOST / SKIPPED (by design) / REJECTED, all channels")
                            : Format("%-*s %-14s %7s %8s  %-22s %9s %9s %8s %7s %8s %8s", w, "PROCESS", "STATE",
                                     "PID", "UPTIME", "CHANNEL", "IN", "OUT", "RATE/s", "LOST", "SKIPPED",
                                     "REJECTED"));
  for (const auto& row : rows) {
    // The state whole (the process's own word), even past its column.
    std::string line =
        Format("%-*s %-14s %7d %8s", w, row.who.c_str(), row.state.c_str(), row.pid, row.uptime.c_str());
    if (condensed) {
      ChannelRow total;
      for (const auto& c : row.channels) {
        total.in += c.in;
        total.out += c.out;
        total.lost += c.lost;
        total.skipped += c.skipped;
        total.rejected += c.rejected;
      }
      line += Format("  %lld / %lld / %lld / %lld / %lld", (long long)total.in, (long long)total.out,
                     (long long)total.lost, (long long)total.skipped, (long long)total.rejected);
    }
    lines.push_back(line);
    if (!condensed)
      for (const auto& c : row.channels)
        lines.push_back(Format("%-*s %-14s %7s %8s  %-22s %9lld %9lld %8s %7lld %8lld %8lld", w, "", "", "", "",
                               c.channel.c_str(), (long long)c.in, (long long)c.out,
                               c.rate < 0 ? "-" : Format("%.1f", c.rate).c_str(), (long long)c.lost,
                               (long long)c.skipped, (long long)c.rejected));
    if (!condensed && !row.stages.empty())
      for (const std::string& stage_line : StageLines(row, cols)) lines.push_back(stage_line);
    if (!row.last_error.empty()) lines.push_back("    last error: " + row.last_error);
  }
  if (lines.size() == 1) lines.push_back("(no PROCESS_STATUS heard yet)");
  return lines;
}

std::vector<std::string> StatusBoard::SummaryLines(int64_t now_us, int cols) const {
  std::vector<std::string> lines;
  if (depth_) {
    const auto& d = *depth_;
    const auto& stats = d.latest;
    std::string line = "depth: ";
    if (now_us - d.heard_us > kGoneAfterUs) {
      line += Format("no cloud for %llds", (long long)((now_us - d.heard_us) / 1000000));
    } else {
      const int points = stats.nstages ? stats.stage_points.back() : 0;
      const double seconds = (d.heard_us - d.first_us) * 1e-6;
      line += Format("%d points (frame %lld)", points, (long long)stats.frame_id);
      line += stats.plane_found ? Format(", plane %.3f m away (inlier RMS %.1f mm)", std::abs(stats.plane_offset),
                                         stats.inlier_rms * 1e3)
                                : std::string(", no plane");
      if (d.clouds > 1 && seconds > 0) line += Format(", %.1f clouds/s", (d.clouds - 1) / seconds);
    }
    lines.push_back(line);
  }
  if (calibration_) {
    const auto& c = *calibration_;
    lines.push_back(Format("calibration: %s  views left %d right %d stereo %d  coverage left %d%% "
                           "right %d%%  rms %s  held-out %s",
                           c.state.c_str(), c.views_left, c.views_right, c.views_stereo,
                           CoveragePercent(c.coverage_left), CoveragePercent(c.coverage_right),
                           c.rms < 0 ? "-" : Format("%.3f px", c.rms).c_str(),
                           c.heldout_rms < 0 ? "-" : Format("%.3f px", c.heldout_rms).c_str()));
    if (!c.hint.empty())
      for (const std::string& line : Wrapped("hint: ", c.hint, cols)) lines.push_back(line);
  }
  if (health_) {
    const auto& h = *health_;
    lines.push_back(Format("health: %-10s median |dy| %s  p95 %s  (max %.2f px; %d matches in %d frames)",
                           h.verdict.c_str(),
                           h.dy_median_px < 0 ? "-" : Format("%.3f px", h.dy_median_px).c_str(),
                           h.dy_p95_px < 0 ? "-" : Format("%.3f px", h.dy_p95_px).c_str(), h.max_dy_px,
                           h.matches, h.frames));
  }
  return lines;
}

std::string StatusBoard::Render(int64_t now_us, Screen screen) const {
  const std::vector<std::string> summary = SummaryLines(now_us, screen.cols);
  std::vector<std::string> table = ProcessLines(now_us, false, screen.cols);
  const size_t room = screen.rows > 0 ? size_t(std::max(2, screen.rows - 1)) : SIZE_MAX;  // the cursor's line
  const size_t gap = summary.empty() ? 0 : 1;
  if (table.size() + gap + summary.size() > room) table = ProcessLines(now_us, true, screen.cols);
  if (table.size() + gap + summary.size() > room) {
    const size_t keep = room > gap + summary.size() + 1 ? room - gap - summary.size() - 1 : 1;
    const size_t cut = table.size() - std::min(keep, table.size());
    table.resize(keep);
    table.push_back(Format("... %zu more lines: a taller terminal shows them", cut));
  }
  std::ostringstream out;
  auto put = [&](const std::string& line) {
    out << (screen.cols > 0 && int(line.size()) > screen.cols ? line.substr(0, size_t(screen.cols)) : line)
        << "\n";
  };
  for (const auto& line : table) put(line);
  if (gap) out << "\n";
  for (const auto& line : summary) put(line);
  return out.str();
}

}  // namespace ws
