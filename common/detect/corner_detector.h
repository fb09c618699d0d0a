// Finding a calibration board's corners in one image. Every detector returns
// corners with the ids of board_spec.h, so object points follow from the ids
// and left and right images of a pair agree on which corner is which.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "board/board_spec.h"

namespace ws {

struct BoardCorners {
  std::vector<int> ids;              // board corner ids (board_spec.h)
  std::vector<cv::Point2f> points;   // sub-pixel image positions, pixel centres at integers
  int unrefined = 0;                 // corners found but dropped: their refinement failed
                                     // (corner_refinement.h)
  bool empty() const { return ids.empty(); }
};

class CornerDetector {
 public:
  virtual ~CornerDetector() = default;
  // Finds the board in an 8-bit single-channel image; no corners when the
  // board is not seen. Safe to call from several threads at once.
  virtual BoardCorners Detect(const cv::Mat& gray) const = 0;
};

// The chessboard detectors.
enum class ChessboardMethod {
  sb,       // cv::findChessboardCornersSB (localized Radon transform), then the saddle points
  classic,  // cv::findChessboardCorners + cv::cornerSubPix, then the saddle points
  opencv,   // OpenCV's own way, for comparison: cv::findChessboardCorners with adaptive
            // threshold and normalisation at full resolution, then cv::cornerSubPix only
};
// sb and classic refine their corners to the same saddle points
// (corner_refinement.h; tests/detect/test_detector_accuracy.cpp measures
// them against exact ground truth); classic is the default.
inline constexpr ChessboardMethod kDefaultChessboardMethod = ChessboardMethod::classic;

// "sb", "classic" or "opencv"; throws std::invalid_argument otherwise.
ChessboardMethod ParseChessboardMethod(const std::string& name);
const char* ChessboardMethodName(ChessboardMethod method);

// How far the classic detector searches before it gives up on an image
// (chessboard_detectors.cpp). The last search finds the boards the others
// miss but costs seconds on every image without a whole board, over a
// minute at 1280 x 960 (bench/detect/README.md): worth it where every image
// counts, not on a live stream, where the next frame replaces a missed one.
enum class BoardSearch {
  kFast,        // the three fast searches: live and replayed logs (stereo-detect)
  kEveryBoard,  // and then OpenCV's own call: a folder of images (stereo-calibrate --images)
};

// A detector for `board`; `method` chooses the chessboard detector (ChArUco
// boards have one), `search` how far the classic one searches (the others
// ignore it).
std::unique_ptr<CornerDetector> MakeCornerDetector(const BoardSpec& board,
                                                   ChessboardMethod method = kDefaultChessboardMethod,
                                                   BoardSearch search = BoardSearch::kFast);

}  // namespace ws
