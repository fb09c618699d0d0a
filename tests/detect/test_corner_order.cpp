// Corner ids mean the same board corner whichever detector found them, in
// whatever pose, in the left and in the right image.
#include <gtest/gtest.h>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>

#include "detect/grid_order.h"
#include "detect_test_views.h"

namespace {

using namespace ws;
using ws::test::kOpenCvData;
using ws::test::kOpenCvDocPairs;

cv::Mat OpenCvDocImage(const std::string& side, int index) {
  const std::string path = kOpenCvData + "/" + ws::test::OpenCvDocName(side, index);
  cv::Mat image = cv::imread(path, cv::IMREAD_GRAYSCALE);
  if (image.empty()) ADD_FAILURE() << "cannot read " << path << " (package opencv-doc)";
  return image;
}

double MaxDistance(const BoardCorners& a, const BoardCorners& b) {
  EXPECT_EQ(a.ids, b.ids);
  double worst = 0;
  for (size_t i = 0; i < std::min(a.points.size(), b.points.size()); ++i)
    worst = std::max(worst, double(cv::norm(a.points[i] - b.points[i])));
  return worst;
}

// findChessboardCornersSB starts these grids at the opposite end from
// findChessboardCorners; after ordering both agree, in the order
// findChessboardCorners gives, and left and right agree with each other.
// "Agree" is within 5 px: where the squares of the photographed board do not
// quite meet (its top row), the two detectors put a corner up to 4 px apart;
// a wrong id would be a whole square, over 20 px, away.
TEST(CornerOrder, BothDetectorsAgreeOnTheOpenCvDocImages) {
  const BoardSpec board = ParseBoardSpec("chessboard:9x6:0.025");
  const auto sb = MakeCornerDetector(board, ChessboardMethod::sb);
  const auto classic = MakeCornerDetector(board, ChessboardMethod::classic);
  for (int index : kOpenCvDocPairs) {
    std::vector<cv::Point2f> diagonal;  // corner 0 to corner 53, left then right
    for (const std::string side : {"left", "right"}) {
      SCOPED_TRACE(side + std::to_string(index));
      const cv::Mat image = OpenCvDocImage(side, index);
      const BoardCorners a = sb->Detect(image), b = classic->Detect(image);
      ASSERT_EQ(a.ids.size(), 54u);
      ASSERT_EQ(b.ids.size(), 54u);
      EXPECT_LT(MaxDistance(a, b), 5.0);
      std::vector<cv::Point2f> opencv;
      ASSERT_TRUE(cv::findChessboardCorners(image, board.pattern_size(), opencv));
      EXPECT_LT(cv::norm(opencv.front() - b.points.front()), 5.0);
      diagonal.push_back(b.points.back() - b.points.front());
    }
    // The rig is side by side: the board's diagonal points the same way in both.
    const double cosine = diagonal[0].dot(diagonal[1]) / (cv::norm(diagonal[0]) * cv::norm(diagonal[1]));
    EXPECT_GT(cosine, 0.9) << "pair " << index;
  }
}

// Turned all the way round, and tilted: every corner gets its true id.
TEST(CornerOrder, IdsAreTheBoardsInEveryRoll) {
  const BoardSpec board = ParseBoardSpec("chessboard:9x6:0.025");
  for (ChessboardMethod method : {ChessboardMethod::sb, ChessboardMethod::classic}) {
    const auto detector = MakeCornerDetector(board, method);
    for (int roll = 0; roll < 360; roll += 45) {
      SCOPED_TRACE(std::string(ChessboardMethodName(method)) + " roll " + std::to_string(roll));
      BoardPose pose;
      pose.roll_deg = roll;
      pose.tilt_x_deg = roll % 90 == 0 ? 25 : -20;
      pose.fill = 0.5;
      const cv::Size size(640, 480);
      const SyntheticView view = RenderBoard(board, BoardToImage(board, pose, size), {size});
      const BoardCorners found = detector->Detect(view.image);
      ASSERT_EQ(found.ids.size(), 54u);
      for (size_t i = 0; i < found.ids.size(); ++i)
        ASSERT_LT(cv::norm(cv::Point2d(found.points[i]) - view.corners[size_t(found.ids[i])]), 0.5) << i;
    }
  }
}

// The grid's symmetries of a detector's output, for OrderChessboardCorners.
std::vector<std::vector<cv::Point2f>> Symmetries(const std::vector<cv::Point2d>& grid, cv::Size pattern) {
  std::vector<std::vector<cv::Point2f>> all;
  for (bool flip_rows : {false, true})
    for (bool flip_cols : {false, true}) {
      std::vector<cv::Point2f> order;
      for (int row = 0; row < pattern.height; ++row)
        for (int col = 0; col < pattern.width; ++col)
          order.emplace_back(grid[(flip_rows ? pattern.height - 1 - row : row) * pattern.width +
                                  (flip_cols ? pattern.width - 1 - col : col)]);
      all.push_back(order);
    }
  return all;
}

TEST(CornerOrder, AnyStartingCornerOfAnAsymmetricBoardGivesTheTrueOrder) {
  const BoardSpec board = ParseBoardSpec("chessboard:9x6:0.025");
  BoardPose pose;
  pose.roll_deg = 150;
  const cv::Size size(640, 480);
  const SyntheticView view = RenderBoard(board, BoardToImage(board, pose, size), {size});
  for (auto corners : Symmetries(view.corners, board.pattern_size())) {
    ASSERT_TRUE(OrderChessboardCorners(view.image, board.pattern_size(), corners));
    for (size_t i = 0; i < corners.size(); ++i)
      ASSERT_LT(cv::norm(cv::Point2d(corners[i]) - view.corners[i]), 1e-3) << i;
  }
}

// 8x6 looks the same turned 180 degrees: corner 0 is then the upper end.
TEST(CornerOrder, SymmetricBoardStartsAtTheUpperEnd) {
  const BoardSpec board = ParseBoardSpec("chessboard:8x6:0.025");
  for (double roll : {20.0, 160.0}) {
    BoardPose pose;
    pose.roll_deg = roll;
    const cv::Size size(640, 480);
    const SyntheticView view = RenderBoard(board, BoardToImage(board, pose, size), {size});
    std::vector<cv::Point2f> first;
    for (auto corners : Symmetries(view.corners, board.pattern_size())) {
      ASSERT_TRUE(OrderChessboardCorners(view.image, board.pattern_size(), corners));
      if (first.empty()) first = corners;
      EXPECT_EQ(corners, first);
      EXPECT_LT(corners.front().y, corners.back().y);
    }
  }
}

TEST(CornerOrder, DegenerateGridIsRefused) {
  const cv::Mat image(480, 640, CV_8UC1, cv::Scalar(128));
  std::vector<cv::Point2f> collinear;
  for (int i = 0; i < 54; ++i) collinear.emplace_back(10.0f + i, 10.0f + i);
  EXPECT_FALSE(OrderChessboardCorners(image, {9, 6}, collinear));
}

}  // namespace
