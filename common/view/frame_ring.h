// The last thumbnails stereo-detect sent (STEREO_THUMBNAILS,
// detect/thumbnail_frame.h), held as they came, so that the view list can
// draw a view with one once its corners come (just after). Bounded: at most
// kFramesHeld frames and kBytesHeld bytes of images, the oldest forgotten
// first (a thumbnail is 12 KB: 128 of them are 25 s of a detector at 5 Hz;
// the byte bound holds whatever a sender puts on the channel). Not
// thread-safe: the input thread's.
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
