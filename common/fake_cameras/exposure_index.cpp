#include "fake_cameras/exposure_index.h"

#include <cstdlib>

namespace ws {

int64_t ExposureIndex::Assign(Side side, int64_t timestamp_ns, bool first_of_stream) {
  const int s = side == Side::left ? 0 : 1;
  std::lock_guard<std::mutex> lock(mutex_);
  if (first_of_stream) return index_ < 0 ? 0 : index_;
  const bool joins =
      index_ >= 0 && !taken_[s] && std::llabs(timestamp_ns - moment_ns_) <= together_ns_;
  if (!joins) {
    ++index_;
    moment_ns_ = timestamp_ns;
    taken_[0] = taken_[1] = false;
  }
  taken_[s] = true;
  return index_;
}

}  // namespace ws
