// OpenCV's two chessboard detectors behind CornerDetector; both return the
// complete grid or nothing, in the order of grid_order.h.
#pragma once

#include "detect/corner_detector.h"

namespace ws {

// cv::findChessboardCornersSB: sub-pixel positions from the detector itself.
class SbChessboardDetector : public CornerDetector {
 public:
  explicit SbChessboardDetector(const BoardSpec& board) : pattern_(board.pattern_size()) {}
  BoardCorners Detect(const cv::Mat& gray) const override;

 private:
  cv::Size pattern_;
};

// cv::findChessboardCorners, refined by cv::cornerSubPix in a window sized to
// the board's squares in the image. Finds boards with squares of 16 pixels and
// more (sb: 9 and more).
//
// Flags: CALIB_CB_NORMALIZE_IMAGE only. Measured on OpenCV 4.6, 1280x960:
// with CALIB_CB_ADAPTIVE_THRESH a frame without a board costs up to seconds
// (2.4 s for the opencv-doc aloeL.jpg, 166 s for uniform noise), and
// CALIB_CB_FAST_CHECK costs 2 s on some frames with a board (its fallback
// check) while not bounding the rest; without them every image tried took
// 1-13 ms with a board and at most 0.13 s without, and the same boards were found.
class ClassicChessboardDetector : public CornerDetector {
 public:
  explicit ClassicChessboardDetector(const BoardSpec& board) : pattern_(board.pattern_size()) {}
  BoardCorners Detect(const cv::Mat& gray) const override;

 private:
  cv::Size pattern_;
};

}  // namespace ws
