#include "capture/aravis_stereo_pair.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <thread>

namespace ws {
namespace {

using Clock = std::chrono::steady_clock;

// Frames that may wait for a partner per side: enough for a partner a couple
// of frames late, few enough to bound memory.
constexpr size_t kMaxWaitingFrames = 4;
// While one camera is away, how often the other one's frames are counted.
constexpr std::chrono::milliseconds kAwayPoll{50};

std::string Trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

}  // namespace

std::pair<std::string, std::string> ParseAravisCameraIds(const std::string& ids) {
  const auto comma = ids.find(',');
  const std::string left = Trim(ids.substr(0, comma));
  const std::string right = comma == std::string::npos ? "" : Trim(ids.substr(comma + 1));
  if (left.empty() || right.empty() || right.find(',') != std::string::npos)
    throw std::invalid_argument("expected two camera ids, LEFT_ID,RIGHT_ID, got '" + ids + "'");
  return {left, right};
}

AravisStereoPair::AravisStereoPair(const std::string& left_id, const std::string& right_id,
                                   const ArvCameraSettings& settings, AravisCameraOptions options)
    : settings_(settings),
      period_(std::llround(1e9 / settings.frame_rate_hz)),
      left_(left_id, settings, options),
      right_(right_id, settings, options),
      pairer_(std::llround(settings.pairing_tolerance_ms * 1e6), kMaxWaitingFrames,
              settings.pairing_clock),
      next_trigger_(Clock::now()) {}

std::optional<StereoFrame> AravisStereoPair::Next(std::chrono::milliseconds timeout) {
  const auto deadline = Clock::now() + timeout;
  const bool software = settings_.trigger == TriggerMode::software;
  while (true) {
    if (auto pair = pairer_.Take()) {
      ++pairs_;
      awaiting_frames_ = false;
      return pair;
    }
    const auto now = Clock::now();
    if (now >= deadline) return std::nullopt;
    auto wait_until = deadline;
    if (software) {
      if (now >= next_trigger_) {
        left_.RequestTrigger();
        right_.RequestTrigger();
        awaiting_frames_ = true;
        next_trigger_ += period_;
        if (next_trigger_ <= now) next_trigger_ = now + period_;  // no burst after a stall
      }
      wait_until = std::min(deadline, next_trigger_);
      if (!awaiting_frames_) {  // nothing can arrive before the next trigger
        std::this_thread::sleep_until(wait_until);
        continue;
      }
    }
    const Side missing = pairer_.Waiting(Side::left) ? Side::right : Side::left;
    if (!Camera(missing).connected()) {
      Drain(missing == Side::left ? Side::right : Side::left);
      wait_until = std::min(wait_until, now + kAwayPoll);
    }
    GrabResult result = Camera(missing).Grab(
        std::chrono::ceil<std::chrono::milliseconds>(wait_until - Clock::now()));
    if (result.status == GrabStatus::frame) pairer_.Add(missing, std::move(result.frame));
  }
}

void AravisStereoPair::Drain(Side side) {
  for (;;) {
    GrabResult result = Camera(side).Grab(std::chrono::milliseconds(0));
    if (result.status == GrabStatus::frame)
      pairer_.Add(side, std::move(result.frame));
    else if (result.status != GrabStatus::incomplete)
      return;
  }
}

StereoPairCounters AravisStereoPair::counters() const {
  StereoPairCounters counters;
  counters.pairs = pairs_;
  counters.unpaired_left = pairer_.unpaired(Side::left);
  counters.unpaired_right = pairer_.unpaired(Side::right);
  counters.left = left_.counters();
  counters.right = right_.counters();
  return counters;
}

std::vector<std::string> AravisStereoPair::TakeEvents() {
  std::vector<std::string> events;
  for (Side side : {Side::left, Side::right})
    for (std::string& event : Camera(side).TakeEvents())
      events.push_back((side == Side::left ? "left " : "right ") + event);
  return events;
}

std::string AravisStereoPair::last_error() const {
  std::string text;
  for (const auto* camera : {&left_, &right_}) {
    const std::string error = camera->last_error();
    if (error.empty()) continue;
    text +=
        (text.empty() ? "" : "; ") + std::string(camera == &left_ ? "left: " : "right: ") + error;
  }
  return text;
}

}  // namespace ws
