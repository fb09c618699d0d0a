#include "view/frame_ring.h"

namespace ws::view {
namespace {

size_t Bytes(const widestereo::stereo_frame_t& frame) { return frame.left.data.size() + frame.right.data.size(); }

}  // namespace

void FrameRing::Hold(std::shared_ptr<const widestereo::stereo_frame_t> frame) {
  bytes_ += Bytes(*frame);
  frames_.push_back(std::move(frame));
  // A frame larger than the whole budget is not held either.
  while (!frames_.empty() && (frames_.size() > kFramesHeld || bytes_ > kBytesHeld)) {
    bytes_ -= Bytes(*frames_.front());
    frames_.pop_front();
  }
}

std::shared_ptr<const widestereo::stereo_frame_t> FrameRing::Find(int64_t frame_id, int64_t utime) const {
  for (auto frame = frames_.rbegin(); frame != frames_.rend(); ++frame)
    if ((*frame)->frame_id == frame_id && (*frame)->utime == utime) return *frame;
  return nullptr;
}

void FrameRing::Clear() {
  frames_.clear();
  bytes_ = 0;
}

}  // namespace ws::view
