// The launch's recording as the page shows it: the LCM log lcm-logger
// writes, its size against the launch's cap (max_log_mb), and whether the cap
// was reached (the launcher then stops the recording; the processes go on).
// stereo-view reads only the file's size (stat), never its contents.
#pragma once

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

namespace ws::view {

class RecordingWatch {
 public:
  // `path`: the log; `cap_bytes`: the size at which the launcher stops it.
  RecordingWatch(std::string path, double cap_bytes) : path_(std::move(path)), cap_bytes_(cap_bytes) {}

  // Looks at the file at `now_us`; true the first time the cap is seen reached.
  bool Check(int64_t now_us);
  // {"path", "mb", "cap_mb", "capped", "capped_us"}; "mb" null while there is no file.
  nlohmann::json Json() const;
  // "recording stopped: PATH reached its cap of N MB; ..." once capped, else "".
  std::string StoppedText() const;

 private:
  std::string path_;
  double cap_bytes_;
  double bytes_ = -1;  // -1: no file (yet)
  int64_t capped_us_ = 0;  // 0: not capped
};

}  // namespace ws::view
