#include "detect/chessboard_detectors.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "detect/grid_order.h"

namespace ws {
namespace {

BoardCorners CompleteGrid(const cv::Mat& gray, cv::Size pattern, std::vector<cv::Point2f> points) {
  if (int(points.size()) != pattern.area() || !OrderChessboardCorners(gray, pattern, points)) return {};
  BoardCorners corners;
  corners.ids.resize(points.size());
  std::iota(corners.ids.begin(), corners.ids.end(), 0);
  corners.points = std::move(points);
  return corners;
}

// Shortest distance between neighbouring corners of the grid, pixels.
double ShortestSpacing(const std::vector<cv::Point2f>& points, cv::Size pattern) {
  double shortest = INFINITY;
  for (int row = 0; row < pattern.height; ++row)
    for (int col = 0; col < pattern.width; ++col) {
      const cv::Point2f p = points[row * pattern.width + col];
      if (col + 1 < pattern.width) shortest = std::min(shortest, cv::norm(points[row * pattern.width + col + 1] - p));
      if (row + 1 < pattern.height) shortest = std::min(shortest, cv::norm(points[(row + 1) * pattern.width + col] - p));
    }
  return shortest;
}

}  // namespace

BoardCorners SbChessboardDetector::Detect(const cv::Mat& gray) const {
  std::vector<cv::Point2f> points;
  if (!cv::findChessboardCornersSB(gray, pattern_, points, cv::CALIB_CB_NORMALIZE_IMAGE)) return {};
  return CompleteGrid(gray, pattern_, std::move(points));
}

BoardCorners ClassicChessboardDetector::Detect(const cv::Mat& gray) const {
  std::vector<cv::Point2f> points;
  if (!cv::findChessboardCorners(gray, pattern_, points, cv::CALIB_CB_NORMALIZE_IMAGE)) return {};
  // The refinement window must not reach the neighbouring corners.
  const int half = std::clamp(int(ShortestSpacing(points, pattern_) * 0.4), 2, 11);
  cv::cornerSubPix(gray, points, cv::Size(half, half), cv::Size(-1, -1),
                   cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 40, 0.001));
  return CompleteGrid(gray, pattern_, std::move(points));
}

}  // namespace ws
