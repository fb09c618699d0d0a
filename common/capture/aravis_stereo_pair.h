// Stereo pairs from two GenICam cameras (stereo-capture --source
// aravis:LEFT_ID,RIGHT_ID).
//
// Software trigger: every 1/frame_rate_hz both cameras get a trigger. Free
// run: both run at frame_rate_hz. Either way the two frames of a pair are
// matched by timestamp within the pairing tolerance (host arrival time, or the
// cameras' clocks when they share one), frames without a partner are dropped
// and counted, and each camera reconnects by itself when it goes
// away (see AravisCamera); meanwhile the other camera's frames are counted as
// unpaired. Memory is bounded: a few frames wait per side.
#pragma once

#include <chrono>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "capture/aravis_camera.h"
#include "capture/arv_camera_settings.h"
#include "capture/camera_frame.h"
#include "capture/frame_pairer.h"

namespace ws {

struct StereoPairCounters {
  uint64_t pairs = 0;
  uint64_t unpaired_left = 0;  // left frames dropped for want of a right one
  uint64_t unpaired_right = 0;
  CameraCounters left;
  CameraCounters right;
};

// "LEFT_ID,RIGHT_ID" (the part of --source after "aravis:") into the two ids;
// throws std::invalid_argument unless there are exactly two non-empty ids.
std::pair<std::string, std::string> ParseAravisCameraIds(const std::string& ids);

class AravisStereoPair {
 public:
  // Starts connecting to both cameras; the settings must be valid
  // (ValidateArvCameraSettings).
  AravisStereoPair(const std::string& left_id, const std::string& right_id,
                   const ArvCameraSettings& settings, AravisCameraOptions options = {});

  // The next pair, or nothing after `timeout`. Never blocks longer.
  std::optional<StereoFrame> Next(std::chrono::milliseconds timeout);

  bool connected() const { return left_.connected() && right_.connected(); }
  StereoPairCounters counters() const;
  // Both cameras' events (AravisCamera::TakeEvents), each prefixed "left " or "right ".
  std::vector<std::string> TakeEvents();
  // The cameras' last errors, "left: ...; right: ...", "" if none.
  std::string last_error() const;

 private:
  AravisCamera& Camera(Side side) { return side == Side::left ? left_ : right_; }
  // Moves whatever `side` has delivered into the pairer, without waiting.
  void Drain(Side side);

  const ArvCameraSettings settings_;
  const std::chrono::nanoseconds period_;
  AravisCamera left_;
  AravisCamera right_;
  FramePairer pairer_;
  std::chrono::steady_clock::time_point next_trigger_;
  bool awaiting_frames_ = false;  // software trigger: triggered, pair not yet out
  uint64_t pairs_ = 0;
};

}  // namespace ws
