// With BoardSearch::kEveryBoard (a folder of images), the classic detector
// finds every board OpenCV's own cv::findChessboardCorners finds with its
// default flags (CALIB_CB_ADAPTIVE_THRESH | CALIB_CB_NORMALIZE_IMAGE), in
// images of up to 960 pixels a side (larger ones: in their 960-pixel copy):
// on a render that only its last search, the one without FAST_CHECK, finds
// (chessboard_detectors.cpp), and on every image of the real sets. With
// kFast (live) it leaves that search out, and that render's board with it.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>

#include "detect_test_views.h"
#include "test_support.h"

namespace {

using namespace ws;

bool OpenCvFinds(const cv::Mat& gray, cv::Size pattern, int flags) {
  std::vector<cv::Point2f> points;
  return cv::findChessboardCorners(gray, pattern, points, flags);
}

// A 960 x 600 board turned 70 degrees away, its near squares about three
// times as wide as its far ones, the light falling to a third across the
// image: one global threshold cannot split it, FAST_CHECK sees too few
// squares of one size (its band is a factor 1.4), the SB detector misses it,
// and the adaptive search at full resolution finds it. The live detector
// (kFast) does not run that search, which costs seconds on every frame
// without a board, so it misses this board.
TEST(BoardSearch, FindsABoardOnlyTheSearchWithoutFastCheckFinds) {
  const BoardSpec board = ParseBoardSpec("chessboard:9x6:0.025");
  const cv::Size size(960, 600);
  BoardPose pose;
  pose.tilt_y_deg = 70;
  pose.fill = 0.3;
  RenderSettings settings;
  settings.size = size;
  settings.blur_sigma = 1;
  settings.light_falloff = 3;
  const SyntheticView view = RenderBoard(board, BoardToImage(board, pose, size), settings);

  const cv::Size pattern = board.pattern_size();
  ASSERT_FALSE(OpenCvFinds(view.image, pattern, cv::CALIB_CB_NORMALIZE_IMAGE)) << "global threshold";
  ASSERT_FALSE(OpenCvFinds(view.image, pattern,
                           cv::CALIB_CB_ADAPTIVE_THRESH | cv::CALIB_CB_NORMALIZE_IMAGE | cv::CALIB_CB_FAST_CHECK))
      << "FAST_CHECK";
  std::vector<cv::Point2f> sb;
  ASSERT_FALSE(cv::findChessboardCornersSB(view.image, pattern, sb, cv::CALIB_CB_NORMALIZE_IMAGE));
  ASSERT_TRUE(OpenCvFinds(view.image, pattern, cv::CALIB_CB_ADAPTIVE_THRESH | cv::CALIB_CB_NORMALIZE_IMAGE));

  EXPECT_TRUE(MakeCornerDetector(board, ChessboardMethod::classic, BoardSearch::kFast)->Detect(view.image).empty())
      << "the live detector runs the search without FAST_CHECK";
  const auto errors =
      test::MeasureErrors(*MakeCornerDetector(board, ChessboardMethod::classic, BoardSearch::kEveryBoard), {view});
  std::printf("steep, unevenly lit board: %d corners, %.4f px RMS\n", errors.corners, errors.rms_px);
  ASSERT_EQ(errors.views_found, 1);
  EXPECT_EQ(errors.corners, board.corner_count());
  EXPECT_LT(errors.rms_px, 0.1);
}

struct ImageSet {
  std::string name, glob, board;
};

// Boards found in every image of `set` by OpenCV's default call and by the
// classic detector searching for every board; each board OpenCV finds must
// be ours too, whole.
void ExpectEveryOpenCvBoard(const ImageSet& set) {
  std::vector<cv::String> files;
  cv::glob(set.glob, files);
  ASSERT_FALSE(files.empty()) << set.glob;
  const BoardSpec board = ParseBoardSpec(set.board);
  const auto classic = MakeCornerDetector(board, ChessboardMethod::classic, BoardSearch::kEveryBoard);
  int opencv = 0, ours = 0;
  for (const cv::String& file : files) {
    const cv::Mat gray = cv::imread(file, cv::IMREAD_GRAYSCALE);
    ASSERT_FALSE(gray.empty()) << file;
    const BoardCorners found = classic->Detect(gray);
    ours += !found.empty();
    if (!OpenCvFinds(gray, board.pattern_size(), cv::CALIB_CB_ADAPTIVE_THRESH | cv::CALIB_CB_NORMALIZE_IMAGE))
      continue;
    ++opencv;
    EXPECT_EQ(int(found.ids.size()) + found.unrefined, board.corner_count()) << file;
    EXPECT_FALSE(found.empty()) << file << ": OpenCV finds the board, the classic detector does not";
  }
  std::printf("%s: %zu images, boards found by OpenCV %d, by the classic detector %d\n", set.name.c_str(),
              files.size(), opencv, ours);
  EXPECT_GT(opencv, 0) << "a set OpenCV finds no board in tests nothing";
}

TEST(BoardSearch, FindsEveryBoardOpenCvFindsInTheOpenCvDocImages) {
  for (const char* side : {"left", "right"})
    ExpectEveryOpenCvBoard({std::string("opencv-doc ") + side, test::kOpenCvData + "/" + side + "*.jpg",
                            "chessboard:9x6:0.025"});
}

// BabelCalib's ov_plane set is left out: OpenCV finds none of its boards
// (the tags in its squares break the quads), so it would test nothing.
TEST(BoardSearch, FindsEveryBoardOpenCvFindsInTheFisheyeStereoRosSet) {
  const std::string dir = test::SourceDir() + "/../shared/data/fisheye-stereo-ros";
  if (!std::filesystem::is_directory(dir)) GTEST_SKIP() << dir << " is absent (the shared data sets)";
  for (const char* side : {"left", "right"})
    ExpectEveryOpenCvBoard({std::string("fisheye-stereo-ros ") + side, dir + "/" + side + "-*.png",
                            "chessboard:8x6:0.04"});
}

}  // namespace
