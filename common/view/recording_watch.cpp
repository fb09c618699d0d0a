#include "view/recording_watch.h"

#include <sys/stat.h>

#include <cstdio>
#include <vector>

namespace ws::view {
namespace {

struct FileStat {
  double bytes;
  int64_t mtime_us;  // its last write: when the next newer file began
};

std::optional<FileStat> Stat(const std::string& path) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) return std::nullopt;
  return FileStat{double(st.st_size), int64_t(st.st_mtim.tv_sec) * 1000000 + st.st_mtim.tv_nsec / 1000};
}

// The time files[0] (the newest) to files.back() (the oldest) span at
// `now_us`: file i began when file i + 1 was last written; the oldest began
// its own length before its last write, taken as the mean length of the
// files between it and the newest (each complete). Null with fewer than
// three files.
std::optional<double> WindowSeconds(const std::vector<FileStat>& files, int64_t now_us) {
  const size_t oldest = files.size() - 1;
  if (files.size() < 3) return std::nullopt;
  const double mean_us = double(files[1].mtime_us - files[oldest].mtime_us) / double(oldest - 1);
  return (double(now_us - files[oldest].mtime_us) + mean_us) / 1e6;
}

}  // namespace

bool RecordingWatch::Check(int64_t now_us) {
  std::vector<FileStat> files;  // newest first
  if (!rolling()) {
    if (auto file = Stat(path_)) files.push_back(*file);
  } else {
    for (int i = 0; i < files_; ++i)
      if (auto file = Stat(path_ + "." + std::to_string(i))) files.push_back(*file);
  }
  present_ = int(files.size());
  bytes_ = files.empty() ? -1 : 0;
  for (const auto& file : files) bytes_ += file.bytes;
  const bool full = rolling() ? present_ == files_ : bytes_ >= cap_bytes_;
  if (rolling() && full) window_s_ = WindowSeconds(files, now_us);
  if (capped_us_ != 0 || !full) return false;
  capped_us_ = now_us;
  return true;
}

nlohmann::json RecordingWatch::Json() const {
  return {{"path", rolling() ? path_ + ".0" : path_},
          {"mb", bytes_ < 0 ? nlohmann::json() : nlohmann::json(bytes_ / 1e6)},
          {"cap_mb", cap_bytes_ / 1e6},
          {"capped", capped_us_ != 0},
          {"capped_us", capped_us_},
          {"files", present_},
          {"rolling", rolling()},
          {"window_s", window_s_ ? nlohmann::json(*window_s_) : nlohmann::json()}};
}

std::string RecordingWatch::StateText() const {
  if (capped_us_ == 0) return "";
  if (!rolling()) return "recording stopped";
  if (!window_s_) return "recording rolling";
  char text[64];
  std::snprintf(text, sizeof text, "recording rolling: the last %.1f min", *window_s_ / 60);
  return text;
}

std::string RecordingWatch::StoppedText() const {
  if (capped_us_ == 0 || rolling()) return "";
  char cap[32];
  std::snprintf(cap, sizeof cap, "%g", cap_bytes_ / 1e6);
  return "recording stopped: " + path_ + " reached its cap of " + cap +
         " MB (max_log_mb); nothing after is recorded, the processes go on";
}

}  // namespace ws::view
