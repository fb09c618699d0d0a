// Frame indices for the two fake cameras of a simulated rig, so that both
// show the same simulated moment: frames the two cameras expose within
// `together_ns` of each other (one software trigger, one free-run tick) get
// the same index, each later moment the next one. A side never takes one
// moment twice, so a missed trigger costs one frame, not the step; a side that
// exposes while the other is away still takes new indices, as a real scene
// goes on moving, so the two stay in step when the other comes back.
//
// With together_ns equal to the capture's pairing tolerance, and the capture
// pairing by camera timestamps (the fake cameras' clocks are this host's), a
// pair the capture makes shows one moment whatever the host's load. The first
// frame of a stream comes late (see FakeGigeCamera::FrameRequest) and is
// dropped by AravisCamera: it starts no moment, lest it take its side's place
// in the next one.
#pragma once

#include <cstdint>
#include <mutex>

#include "capture/camera_frame.h"

namespace ws {

class ExposureIndex {
 public:
  explicit ExposureIndex(int64_t together_ns) : together_ns_(together_ns) {}

  // The index of a frame `side` exposes at `timestamp_ns`; thread-safe.
  int64_t Assign(Side side, int64_t timestamp_ns, bool first_of_stream);

 private:
  const int64_t together_ns_;
  std::mutex mutex_;
  int64_t index_ = -1;  // of the latest moment
  int64_t moment_ns_ = 0;
  bool taken_[2] = {false, false};
};

}  // namespace ws
