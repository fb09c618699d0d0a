#include "capture/frame_pairer.h"

#include <utility>

namespace ws {

FramePairer::FramePairer(int64_t tolerance_ns, size_t max_waiting, PairingClock clock)
    : tolerance_ns_(tolerance_ns), max_waiting_(max_waiting), clock_(clock) {}

void FramePairer::Add(Side side, CameraFrame frame) {
  Queue(side).push_back(std::move(frame));
  if (Queue(side).size() > max_waiting_) DropOldest(side);
}

std::optional<StereoFrame> FramePairer::Take() {
  auto& left = Queue(Side::left);
  auto& right = Queue(Side::right);
  while (!left.empty() && !right.empty()) {
    const int64_t dt = Stamp(left.front()) - Stamp(right.front());
    if (dt > tolerance_ns_) {
      DropOldest(Side::right);
    } else if (dt < -tolerance_ns_) {
      DropOldest(Side::left);
    } else {
      StereoFrame pair{std::move(left.front()), std::move(right.front())};
      left.pop_front();
      right.pop_front();
      return pair;
    }
  }
  return std::nullopt;
}

int64_t FramePairer::Stamp(const CameraFrame& frame) const {
  return clock_ == PairingClock::host ? frame.host_timestamp_ns : frame.camera_timestamp_ns;
}

void FramePairer::DropOldest(Side side) {
  Queue(side).pop_front();
  ++unpaired_[Index(side)];
}

}  // namespace ws
