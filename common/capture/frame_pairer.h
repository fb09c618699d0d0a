// Pairs the frames of two cameras by timestamp: two frames make a pair when
// their timestamps (host or camera, as chosen) lie within the tolerance of
// each other. Pure logic, no I/O.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>

#include "capture/arv_camera_settings.h"
#include "capture/camera_frame.h"

namespace ws {

class FramePairer {
 public:
  // Keeps at most max_waiting frames per side; beyond that the oldest is dropped.
  FramePairer(int64_t tolerance_ns, size_t max_waiting, PairingClock clock);

  // Frames of one side must come in arrival order.
  void Add(Side side, CameraFrame frame);

  // The oldest pair, if any. Frames older than the other side's oldest by more
  // than the tolerance can never be paired: they are dropped and counted.
  std::optional<StereoFrame> Take();

  bool Waiting(Side side) const { return !Queue(side).empty(); }
  // Frames dropped for want of a partner, per side.
  uint64_t unpaired(Side side) const { return unpaired_[Index(side)]; }

 private:
  static size_t Index(Side side) { return side == Side::left ? 0 : 1; }
  std::deque<CameraFrame>& Queue(Side side) { return queues_[Index(side)]; }
  const std::deque<CameraFrame>& Queue(Side side) const { return queues_[Index(side)]; }
  void DropOldest(Side side);
  int64_t Stamp(const CameraFrame& frame) const;

  int64_t tolerance_ns_;
  size_t max_waiting_;
  PairingClock clock_;
  std::deque<CameraFrame> queues_[2];
  uint64_t unpaired_[2] = {0, 0};
};

}  // namespace ws
