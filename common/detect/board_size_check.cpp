#include "detect/board_size_check.h"

#include <algorithm>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

namespace ws {

std::vector<cv::Size> NeighbourSizes(const BoardSpec& board) {
  // Squares counted for corners first (one more each way), then one side off.
  static const int kSteps[][2] = {{-1, -1}, {-1, 0}, {0, -1}, {1, 0}, {0, 1}, {1, 1}, {-1, 1}, {1, -1}};
  std::vector<cv::Size> sizes;
  for (const auto& step : kSteps) {
    const cv::Size size(board.cols + step[0], board.rows + step[1]);
    if (size.width >= 3 && size.height >= 3) sizes.push_back(size);
  }
  return sizes;
}

bool ShowsChessboard(const cv::Mat& gray, cv::Size size) {
  std::vector<cv::Point2f> corners;
  return cv::findChessboardCorners(
      gray, size, corners, cv::CALIB_CB_ADAPTIVE_THRESH | cv::CALIB_CB_NORMALIZE_IMAGE | cv::CALIB_CB_FAST_CHECK);
}

std::optional<cv::Size> LargerBoardShown(const cv::Mat& gray, const BoardSpec& board,
                                         const std::vector<cv::Point2f>& corners) {
  if (board.type != BoardType::chessboard || corners.empty()) return std::nullopt;
  // A square's side, at most (the board's extent along its longer side, over
  // that side's squares; more where the board is turned).
  const cv::Rect2f found = cv::boundingRect(corners);
  const float square = std::max(found.width, found.height) / float(std::max(board.cols, board.rows) - 1);
  const cv::Rect around = cv::Rect(cv::Point(cvFloor(found.x - 3 * square), cvFloor(found.y - 3 * square)),
                                   cv::Point(cvCeil(found.br().x + 3 * square), cvCeil(found.br().y + 3 * square))) &
                          cv::Rect(0, 0, gray.cols, gray.rows);
  const cv::Mat near = gray(around);
  for (const cv::Size& size : NeighbourSizes(board))
    if (size.width >= board.cols && size.height >= board.rows && ShowsChessboard(near, size)) return size;
  return std::nullopt;
}

std::string WithSize(const BoardSpec& board, cv::Size size) {
  const size_t from = board.id.find(':') + 1;
  const size_t to = board.id.find(':', from);
  return board.id.substr(0, from) + std::to_string(size.width) + "x" + std::to_string(size.height) +
         (to == std::string::npos ? "" : board.id.substr(to));
}

}  // namespace ws
