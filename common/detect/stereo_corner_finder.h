// One stereo frame in, its corners message out: what stereo-detect does to
// every STEREO_IMAGES message.
#pragma once

#include <memory>

#include "board/board_spec.h"
#include "detect/corner_detector.h"
#include "lcm_io/image_codec.h"
#include "widestereo/stereo_corners_t.hpp"
#include "widestereo/stereo_frame_t.hpp"

namespace ws {

class StereoCornerFinder {
 public:
  // Images of more than max_image_pixels are refused before they are decoded;
  // `search` is MakeCornerDetector's (corner_detector.h).
  StereoCornerFinder(BoardSpec board, ChessboardMethod method, BoardSearch search = BoardSearch::kFast,
                     int64_t max_image_pixels = kDefaultMaxImagePixels);

  // The corners of both images, with the frame's utime and frame_id. A camera
  // that does not see the board gets n = 0. Throws DecodeError for an image
  // that does not decode (a JPEG cut short included), that is larger than
  // max_image_pixels, or that is too small to show the board at two pixels
  // per square. Safe to call from several threads at once. `unrefined`, if
  // given, receives how many corners of both images were found but dropped
  // because their refinement failed (BoardCorners::unrefined); the message
  // carries only the corners kept.
  widestereo::stereo_corners_t Find(const widestereo::stereo_frame_t& frame, int* unrefined = nullptr) const;
  widestereo::camera_corners_t FindInImage(const widestereo::image_t& image, int* unrefined = nullptr) const;
  // The corners of a camera a one-camera rig does not have: the board, no
  // corners, no image size.
  widestereo::camera_corners_t NoCamera() const;

  const BoardSpec& board() const { return board_; }

 private:
  BoardSpec board_;
  std::unique_ptr<CornerDetector> detector_;
  int64_t max_image_pixels_;
};

}  // namespace ws
