// ChArUco boards (OpenCV's aruco module): the markers name the corners, so
// any part of the board gives corners with their true ids - boards that run
// off the edge of the field of view included.
#pragma once

#include <opencv2/aruco/charuco.hpp>

#include "detect/corner_detector.h"

namespace ws {

class CharucoDetector : public CornerDetector {
 public:
  explicit CharucoDetector(const BoardSpec& board);
  // The corners next to at least two detected markers, ordered by id, at
  // sub-pixel positions.
  BoardCorners Detect(const cv::Mat& gray) const override;

 private:
  cv::Ptr<cv::aruco::CharucoBoard> board_;
  cv::Ptr<cv::aruco::DetectorParameters> parameters_;
};

}  // namespace ws
