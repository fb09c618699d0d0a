#include "detect/grid_order.h"

#include <opencv2/imgproc.hpp>

namespace ws {
namespace {

// One of the grid's symmetries: corner (row, col) of the new order is corner
// At(row, col) of the detector's order.
struct GridOrder {
  cv::Size pattern;
  bool transpose, flip_rows, flip_cols;

  int At(int row, int col) const {
    if (flip_rows) row = pattern.height - 1 - row;
    if (flip_cols) col = pattern.width - 1 - col;
    return transpose ? col * pattern.height + row : row * pattern.width + col;
  }
};

double Cross(cv::Point2f a, cv::Point2f b) { return double(a.x) * b.y - double(a.y) * b.x; }

// Mean grey level of the inner half of the square whose corners are p[0..3]
// (the mask covers only the square's bounding box: the image may be large).
double SquareBrightness(const cv::Mat& gray, const cv::Point2f (&p)[4]) {
  const cv::Point2f centre = (p[0] + p[1] + p[2] + p[3]) * 0.25f;
  std::vector<cv::Point> inner;
  for (const cv::Point2f& q : p) inner.emplace_back(cv::Point2f(centre + (q - centre) * 0.5f));
  const cv::Rect box = (cv::boundingRect(inner) | cv::Rect(cv::Point(centre), cv::Size(1, 1))) &
                       cv::Rect(0, 0, gray.cols, gray.rows);
  if (box.empty()) return 0;
  for (cv::Point& q : inner) q -= box.tl();
  cv::Mat mask = cv::Mat::zeros(box.size(), CV_8UC1);
  cv::fillConvexPoly(mask, inner, cv::Scalar(255));
  if (cv::countNonZero(mask) == 0) {  // a square of a pixel or so: its centre pixel
    const cv::Point c(centre);
    return box.contains(c) ? gray.at<uint8_t>(c) : 0;
  }
  return cv::mean(gray(box), mask)[0];
}

// Whether the first square of the grid in `order` is darker than the one next to it.
bool FirstSquareIsDark(const cv::Mat& gray, const std::vector<cv::Point2f>& corners, const GridOrder& order) {
  auto square = [&](int col) {
    const cv::Point2f p[4] = {corners[order.At(0, col)], corners[order.At(0, col + 1)],
                              corners[order.At(1, col + 1)], corners[order.At(1, col)]};
    return SquareBrightness(gray, p);
  };
  return square(0) < square(1);
}

}  // namespace

bool OrderChessboardCorners(const cv::Mat& gray, cv::Size pattern, std::vector<cv::Point2f>& corners) {
  CV_Assert(int(corners.size()) == pattern.area() && pattern.width >= 3 && pattern.height >= 2);
  std::vector<GridOrder> candidates;
  for (bool transpose : {false, true}) {
    if (transpose && pattern.width != pattern.height) continue;
    for (bool flip_rows : {false, true})
      for (bool flip_cols : {false, true}) {
        const GridOrder order{pattern, transpose, flip_rows, flip_cols};
        const cv::Point2f origin = corners[order.At(0, 0)];
        if (Cross(corners[order.At(0, 1)] - origin, corners[order.At(1, 0)] - origin) > 0)
          candidates.push_back(order);
      }
  }
  std::vector<GridOrder> dark;
  for (const GridOrder& order : candidates)
    if (FirstSquareIsDark(gray, corners, order)) dark.push_back(order);
  if (!dark.empty()) candidates.swap(dark);
  if (candidates.empty()) return false;

  const GridOrder* best = &candidates.front();
  for (const GridOrder& order : candidates)
    if (corners[order.At(0, 0)].y < corners[best->At(0, 0)].y) best = &order;
  std::vector<cv::Point2f> ordered(corners.size());
  for (int row = 0; row < pattern.height; ++row)
    for (int col = 0; col < pattern.width; ++col)
      ordered[row * pattern.width + col] = corners[best->At(row, col)];
  corners.swap(ordered);
  return true;
}

}  // namespace ws
