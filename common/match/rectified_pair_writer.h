// stereo-match --save-rectified DIR: the rectified pairs as PNG files that a
// user can inspect and a check can find board corners in:
//   DIR/left_NNNNNN.png, DIR/right_NNNNNN.png
// NNNNNN being the frame id zero-padded to 6 digits, for every frame whose id
// is a multiple of save_every (1: every frame).
#pragma once

#include <cstdint>
#include <string>

#include <opencv2/core.hpp>

namespace ws {

struct RectifiedSaveConfig {
  std::string dir;     // "": nothing is written
  int save_every = 1;  // >= 1
};

// DIR/SIDE_NNNNNN.png ("left" or "right").
std::string RectifiedImagePath(const std::string& dir, const std::string& side, int64_t frame_id);

class RectifiedPairWriter {
 public:
  // Creates the folder. Throws std::invalid_argument when save_every < 1,
  // std::runtime_error when the folder cannot be created.
  explicit RectifiedPairWriter(RectifiedSaveConfig config);

  bool Wants(int64_t frame_id) const;
  // Throws std::runtime_error naming the file when it cannot be written.
  void Write(int64_t frame_id, const cv::Mat& left, const cv::Mat& right) const;

 private:
  RectifiedSaveConfig config_;
};

}  // namespace ws
