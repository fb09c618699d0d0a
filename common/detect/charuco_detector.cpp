#include "detect/charuco_detector.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <opencv2/imgproc.hpp>

#include "detect/corner_refinement.h"

namespace ws {
namespace {

// OpenCV 4.6's interpolateCornersCharuco returns corners about (+0.5, +0.5)
// pixel off the true corner (measured on rendered boards: 0.7 px RMS, at
// 640x480 and at 1280x960 alike). cornerSubPix again, from there, in a window
// that stays clear of the corners of the markers next to each corner, brings
// them to 0.03-0.07 px; the saddle points (corner_refinement.h), their
// scales bounded by that clearance, to about 0.02 px.
void RefineClearOfMarkers(const cv::Mat& gray, const std::vector<std::vector<cv::Point2f>>& markers,
                          std::vector<cv::Point2f>& points) {
  std::vector<double> clearances;
  for (cv::Point2f& point : points) {
    double clearance = INFINITY;
    for (const auto& marker : markers)
      for (const cv::Point2f& corner : marker) clearance = std::min(clearance, cv::norm(corner - point));
    const int half = std::clamp(int(clearance * 0.7), 2, 11);
    std::vector<cv::Point2f> one{point};
    cv::cornerSubPix(gray, one, cv::Size(half, half), cv::Size(-1, -1),
                     cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 40, 0.001));
    point = one.front();
    clearances.push_back(clearance);
  }
  RefineCorners(gray, points, clearances, points);
}

}  // namespace

CharucoDetector::CharucoDetector(const BoardSpec& board)
    : board_(cv::aruco::CharucoBoard::create(board.cols + 1, board.rows + 1, float(board.square),
                                             float(board.marker),
                                             cv::aruco::getPredefinedDictionary(board.dictionary))),
      parameters_(cv::aruco::DetectorParameters::create()) {}

BoardCorners CharucoDetector::Detect(const cv::Mat& gray) const {
  std::vector<std::vector<cv::Point2f>> marker_corners;
  std::vector<int> marker_ids;
  cv::aruco::detectMarkers(gray, board_->dictionary, marker_corners, marker_ids, parameters_);
  if (marker_ids.empty()) return {};
  std::vector<cv::Point2f> points;
  std::vector<int> ids;
  cv::aruco::interpolateCornersCharuco(marker_corners, marker_ids, gray, board_, points, ids);
  RefineClearOfMarkers(gray, marker_corners, points);

  std::vector<size_t> by_id(ids.size());
  std::iota(by_id.begin(), by_id.end(), 0);
  std::sort(by_id.begin(), by_id.end(), [&](size_t a, size_t b) { return ids[a] < ids[b]; });
  BoardCorners corners;
  for (size_t i : by_id) {
    corners.ids.push_back(ids[i]);
    corners.points.push_back(points[i]);
  }
  corners.unrefined = DropUnrefined(corners.ids, corners.points);
  return corners;
}

}  // namespace ws
