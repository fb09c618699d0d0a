// The last frames stereo-view heard, held as they came (a PNG or JPEG
// payload stays compressed, nothing is decoded), so that the view list can
// make a thumbnail of one once stereo-detect has found a board in it: the
// corners come later than the frame, by the detector's latency. Bounded:
// at most kFramesHeld frames and kBytesHeld bytes of images, the oldest
// forgotten first: of 1280x960 pairs, 64 PNG ones (1.04 MB each: 13 s at
// 5 Hz) or 27 raw ones (2.46 MB). Not thread-safe: the input thread's.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>

#include "widestereo/stereo_frame_t.hpp"

namespace ws::view {

class FrameRing {
 public:
  static constexpr size_t kFramesHeld = 128;
  static constexpr size_t kBytesHeld = size_t(64) << 20;

  void Hold(std::shared_ptr<const widestereo::stereo_frame_t> frame);
  // The frame of that id and utime, or null when it was never held or is forgotten.
  std::shared_ptr<const widestereo::stereo_frame_t> Find(int64_t frame_id, int64_t utime) const;
  // Forgets every frame (when no detector is heard: nothing will ask).
  void Clear();
  size_t frames() const { return frames_.size(); }
  size_t bytes() const { return bytes_; }

 private:
  std::deque<std::shared_ptr<const widestereo::stereo_frame_t>> frames_;  // oldest first
  size_t bytes_ = 0;
};

}  // namespace ws::view
