// Where stereo-capture's pairs come from: cameras, an image directory, or the
// simulator. Each source yields pairs until it ends (or forever).
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace ws {

struct StereoPair {
  cv::Mat left;
  cv::Mat right;
  int64_t utime = 0;     // capture time when the source knows it (cameras), else 0
  std::string label;     // where it came from, for logs (file names, camera ids)
  // No pair was due yet (cameras still connecting or silent): not a lost
  // frame, just a chance for the caller to look up; the label says why.
  bool nothing_due = false;
};

struct SourceCounts {
  int64_t received = 0;
  int64_t dropped = 0;
  int64_t rejected = 0;
};

class StereoSource {
 public:
  virtual ~StereoSource() = default;
  // The next pair, or nothing when the source has ended. May block up to
  // about a second (cameras). A pair with empty images is a frame that was
  // due but could not be had (a timeout, an unreadable file): its label says why.
  virtual std::optional<StereoPair> Next() = 0;
  // Counts per input of the source (a camera, a directory), reported in
  // PROCESS_STATUS like channels: frames received, lost (dropped) and
  // incomplete or unreadable (rejected).
  virtual std::map<std::string, SourceCounts> Counters() const = 0;
  // What happened since the last call (connections, losses), for the log.
  virtual std::vector<std::string> TakeEvents() { return {}; }
  // True when pairs come at the source's own pace (cameras): no rate limit.
  virtual bool Paced() const { return false; }
  // True for a one-camera rig: every pair has a left image only.
  virtual bool Mono() const { return false; }
};

}  // namespace ws
