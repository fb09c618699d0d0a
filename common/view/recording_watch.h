// The launch's recording as the page shows it: the LCM log lcm-logger
// writes, its size against the launch's cap (max_log_mb), and whether the cap
// was reached. With one file the launcher then stops the recording (the
// processes go on). A rolling recording (the launch's rolling_log) is
// `files` files, <log>.0 the newest, each begun once the one before passed
// cap / files, the oldest deleted: it never stops and holds the last minutes,
// how many the page says (Json "window_s").
// stereo-view reads only the files' sizes and times (stat), never their contents.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace ws::view {

class RecordingWatch {
 public:
  // `path`: the log (rolling: the name before .0); `cap_bytes`: the size at
  // which the launcher stops it, or that a rolling one keeps; `files`: 1, or
  // a rolling recording's number of files.
  RecordingWatch(std::string path, double cap_bytes, int files = 1)
      : path_(std::move(path)), cap_bytes_(cap_bytes), files_(files) {}

  // Looks at the files at `now_us`; true the first time the cap is seen
  // reached (rolling: the last file begun, the oldest deleted from then on).
  bool Check(int64_t now_us);
  // {"path", "mb", "cap_mb", "capped", "capped_us", "files", "rolling",
  // "window_s"}: "mb" null while there is no file; "files" those there;
  // "window_s" the time a full rolling recording spans, else null.
  nlohmann::json Json() const;
  // What stereo-status shows as stereo-view's state once capped: "recording
  // stopped", or "recording rolling: the last 4.2 min"; else "".
  std::string StateText() const;
  // "recording stopped: PATH reached its cap of N MB; ..." once a one-file
  // recording is capped, else "".
  std::string StoppedText() const;

 private:
  bool rolling() const { return files_ > 1; }
  std::string path_;
  double cap_bytes_;
  int files_;
  double bytes_ = -1;  // -1: no file (yet)
  int present_ = 0;    // files there
  int64_t capped_us_ = 0;  // 0: not capped
  std::optional<double> window_s_;
};

}  // namespace ws::view
