// stereo-match's images of a frame as PNG files that a user can inspect and a
// check can read: --save-rectified (the rectified pair, in which a check can
// find board corners) and --save-disparity (the disparity in colour with its
// legend in metres, view/disparity_colour.h):
//   DIR/left_NNNNNN.png, DIR/right_NNNNNN.png, DIR/disparity_NNNNNN.png
// NNNNNN being the frame id zero-padded to 6 digits, for every frame whose id
// is a multiple of save_every (1: every frame).
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <opencv2/core.hpp>

namespace ws {

struct ImageSaveConfig {
  std::string dir;     // "": nothing is written
  int save_every = 1;  // >= 1
};

// DIR/NAME_NNNNNN.png ("left", "right", "disparity").
std::string FrameImagePath(const std::string& dir, const std::string& name, int64_t frame_id);

class FrameImageWriter {
 public:
  // Creates the folder; `option` names it in errors ("--save-rectified").
  // Throws std::invalid_argument when save_every < 1, std::runtime_error
  // when the folder cannot be created.
  FrameImageWriter(ImageSaveConfig config, std::string option);

  bool Wants(int64_t frame_id) const;
  // Each (name, image) as FrameImagePath(dir, name, frame_id). Throws
  // std::runtime_error naming the file when one cannot be written.
  void Write(int64_t frame_id, const std::vector<std::pair<std::string, cv::Mat>>& images) const;

 private:
  ImageSaveConfig config_;
  std::string option_;
};

}  // namespace ws
