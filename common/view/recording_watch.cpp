#include "view/recording_watch.h"

#include <sys/stat.h>

#include <cstdio>

namespace ws::view {

bool RecordingWatch::Check(int64_t now_us) {
  struct stat st {};
  bytes_ = stat(path_.c_str(), &st) == 0 ? double(st.st_size) : -1;
  if (capped_us_ != 0 || bytes_ < cap_bytes_) return false;
  capped_us_ = now_us;
  return true;
}

nlohmann::json RecordingWatch::Json() const {
  return {{"path", path_},
          {"mb", bytes_ < 0 ? nlohmann::json() : nlohmann::json(bytes_ / 1e6)},
          {"cap_mb", cap_bytes_ / 1e6},
          {"capped", capped_us_ != 0},
          {"capped_us", capped_us_}};
}

std::string RecordingWatch::StoppedText() const {
  if (capped_us_ == 0) return "";
  char cap[32];
  std::snprintf(cap, sizeof cap, "%g", cap_bytes_ / 1e6);
  return "recording stopped: " + path_ + " reached its cap of " + cap +
         " MB (max_log_mb); nothing after is recorded, the processes go on";
}

}  // namespace ws::view
