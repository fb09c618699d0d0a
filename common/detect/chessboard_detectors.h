// The chessboard detectors behind CornerDetector; each returns the complete
// grid or nothing, in the order of grid_order.h.
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

// cv::findChessboardCorners (chessboard_detectors.cpp says which of its
// searches, cheapest first; the SB detector third, then, with
// BoardSearch::kEveryBoard, OpenCV's own call with its default flags),
// refined by cv::cornerSubPix in a window sized to the board's squares in
// the image, then to the saddle points; corners whose refinement failed are
// dropped and counted (corner_refinement.h). With kEveryBoard it finds
// every board cv::findChessboardCorners finds with its default flags
// (CALIB_CB_ADAPTIVE_THRESH | CALIB_CB_NORMALIZE_IMAGE), and more: boards
// with squares of 16 pixels and more (sb: 9 and more).
//
// The searches run without CALIB_CB_ADAPTIVE_THRESH at first and with
// CALIB_CB_FAST_CHECK where it is set; the fast path took 1-13 ms with a
// board (OpenCV 4.6, 1280x960). A frame without a board goes through them
// all: 0.06-8 s with kFast, 0.3-80 s with kEveryBoard, whose last call
// dominates (bench/detect/README.md).
class ClassicChessboardDetector : public CornerDetector {
 public:
  explicit ClassicChessboardDetector(const BoardSpec& board, BoardSearch search = BoardSearch::kFast)
      : pattern_(board.pattern_size()), search_(search) {}
  BoardCorners Detect(const cv::Mat& gray) const override;

 private:
  cv::Size pattern_;
  BoardSearch search_;
};

// OpenCV's own detection, as its documentation calls it, for comparison:
// cv::findChessboardCorners with CALIB_CB_ADAPTIVE_THRESH |
// CALIB_CB_NORMALIZE_IMAGE at full resolution, then cv::cornerSubPix in the
// same window as the classic detector's, and nothing more.
class OpenCvChessboardDetector : public CornerDetector {
 public:
  explicit OpenCvChessboardDetector(const BoardSpec& board) : pattern_(board.pattern_size()) {}
  BoardCorners Detect(const cv::Mat& gray) const override;

 private:
  cv::Size pattern_;
};

}  // namespace ws
