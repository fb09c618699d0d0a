#include "detect/chessboard_detectors.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "detect/grid_order.h"
#include "detect/corner_refinement.h"

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

// Each corner's distance to its nearest neighbour in the grid, pixels.
std::vector<double> NearestSpacing(const std::vector<cv::Point2f>& points, cv::Size pattern) {
  std::vector<double> nearest(points.size(), INFINITY);
  auto link = [&](int a, int b) {
    const double d = cv::norm(points[a] - points[b]);
    nearest[a] = std::min(nearest[a], d);
    nearest[b] = std::min(nearest[b], d);
  };
  for (int row = 0; row < pattern.height; ++row)
    for (int col = 0; col < pattern.width; ++col) {
      const int i = row * pattern.width + col;
      if (col + 1 < pattern.width) link(i, i + 1);
      if (row + 1 < pattern.height) link(i, i + pattern.width);
    }
  return nearest;
}

// A copy of at most `side` pixels a side for OpenCV's adaptive-threshold
// search, whose cost grows steeply with the image (about 11 s on a 1280 x
// 960 simulator frame holding part of a board, 1 s on its 800-pixel copy);
// the corners are refined at full resolution afterwards.
struct SearchCopy {
  SearchCopy(const cv::Mat& gray, int side)
      : scale(std::min(1.0, double(side) / std::max(gray.cols, gray.rows))), image(gray) {
    if (scale < 1) cv::resize(gray, image, cv::Size(), scale, scale, cv::INTER_AREA);
  }
  double scale;
  cv::Mat image;
};

// OpenCV's adaptive-threshold search, which finds boards in unevenly lit
// images that one global threshold misses, on `copy`. With `fast_check`,
// FAST_CHECK leaves frames without a board early.
bool AdaptiveSearch(const SearchCopy& copy, cv::Size pattern, bool fast_check, std::vector<cv::Point2f>* points) {
  if (!cv::findChessboardCorners(copy.image, pattern, *points,
                                 cv::CALIB_CB_ADAPTIVE_THRESH | cv::CALIB_CB_NORMALIZE_IMAGE |
                                     (fast_check ? cv::CALIB_CB_FAST_CHECK : 0)))
    return false;
  for (cv::Point2f& p : *points)
    p = (p + cv::Point2f(0.5f, 0.5f)) / copy.scale - cv::Point2f(0.5f, 0.5f);
  return true;
}

// Where the board is, by the cheapest search that finds it:
//   1. one global threshold (the fast path), at full resolution;
//   2. the adaptive threshold with FAST_CHECK on a copy of at most 800
//      pixels a side (960 with BoardSearch::kEveryBoard);
//   3. the SB detector at full resolution: it finds boards the quads of 1
//      and 2 miss (blurred, small or strongly curved squares);
//   4. with BoardSearch::kEveryBoard only, before giving up, OpenCV's own
//      call with its default flags (adaptive threshold and normalisation,
//      no FAST_CHECK) on the same copy of at most 960 pixels a side, so
//      that every board cv::findChessboardCorners finds at that size is
//      found.
// FAST_CHECK rejects boards the full search finds: it looks for at least
// COLS x ROWS / 2 black and white squares whose sizes lie within a factor
// 1.4 of each other, under one global threshold (OpenCV 4.6,
// checkchessboard.cpp), which a board seen steeply (its near squares
// larger than 1.4 times its far ones) or lit unevenly does not give; the
// 800-pixel copy loses boards whose far squares are only a few pixels.
// FAST_CHECK passes when either of two checks does, one of them
// cv::checkChessboard on the image searched (calibinit.cpp), and once it
// passes the search is the one without the flag. So where
// cv::checkChessboard passes on the copy, step 2 was step 4 already, and
// step 4 is not run again: a frame holding part of a board, which passes
// the check, pays for one full search instead of two.
// Step 4 costs nothing on a frame steps 1-3 find a board in; on a frame
// without a whole board it is most of the time spent, and it grows
// steeply with the image: on 1280 x 960 renders holding part of a board,
// 15 to 106 s at full resolution, 1.4 to 3.2 s at 960 pixels, 0.6 to 1 s
// at 800 (where the steep 960 x 600 board of test_board_search.cpp is
// lost). Live, stereo-detect would drop the frames that arrive meanwhile
// (corner_stage.h), so it keeps steps 1-3 (kFast) on the 800-pixel copy:
// a board they miss is seen again in the next frames. A folder of images
// for calibration (stereo-calibrate --images) has no next frame, so it
// runs step 4 too (docs/capture.md).
bool FindBoard(const cv::Mat& gray, cv::Size pattern, BoardSearch search, std::vector<cv::Point2f>* points) {
  constexpr int kSearchSide = 800, kEveryBoardSide = 960;
  if (cv::findChessboardCorners(gray, pattern, *points, cv::CALIB_CB_NORMALIZE_IMAGE)) return true;
  const bool every_board = search == BoardSearch::kEveryBoard;
  const SearchCopy copy(gray, every_board ? kEveryBoardSide : kSearchSide);
  return AdaptiveSearch(copy, pattern, true, points) ||
         cv::findChessboardCornersSB(gray, pattern, *points, cv::CALIB_CB_NORMALIZE_IMAGE) ||
         (every_board && !cv::checkChessboard(copy.image, pattern) && AdaptiveSearch(copy, pattern, false, points));
}

// The detector's corners to their saddle points (corner_refinement.h), each
// fit starting there, cornerSubPix's corners where no fit is good; in grid
// order, without the corners whose refinement failed.
BoardCorners RefinedGrid(const cv::Mat& gray, cv::Size pattern, std::vector<cv::Point2f> points) {
  const std::vector<double> spacing = NearestSpacing(points, pattern);
  std::vector<cv::Point2f> subpix = points;
  CornerSubPix(gray, subpix, spacing);
  RefineCorners(gray, points, spacing, subpix);
  BoardCorners corners = CompleteGrid(gray, pattern, std::move(points));
  corners.unrefined = DropUnrefined(corners.ids, corners.points);
  return corners;
}

}  // namespace

BoardCorners SbChessboardDetector::Detect(const cv::Mat& gray) const {
  std::vector<cv::Point2f> points;
  if (!cv::findChessboardCornersSB(gray, pattern_, points, cv::CALIB_CB_NORMALIZE_IMAGE)) return {};
  return RefinedGrid(gray, pattern_, std::move(points));
}

BoardCorners ClassicChessboardDetector::Detect(const cv::Mat& gray) const {
  std::vector<cv::Point2f> points;
  if (!FindBoard(gray, pattern_, search_, &points)) return {};
  return RefinedGrid(gray, pattern_, std::move(points));
}

BoardCorners OpenCvChessboardDetector::Detect(const cv::Mat& gray) const {
  std::vector<cv::Point2f> points;
  if (!cv::findChessboardCorners(gray, pattern_, points,
                                 cv::CALIB_CB_ADAPTIVE_THRESH | cv::CALIB_CB_NORMALIZE_IMAGE))
    return {};
  CornerSubPix(gray, points, NearestSpacing(points, pattern_));
  return CompleteGrid(gray, pattern_, std::move(points));
}

}  // namespace ws
