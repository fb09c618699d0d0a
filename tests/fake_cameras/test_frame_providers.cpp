#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "capture/camera_error.h"
#include "fake_cameras/frame_providers.h"
#include "test_support.h"

namespace {

cv::Mat Uniform(int value) { return cv::Mat(4, 6, CV_8UC1, cv::Scalar(value)); }

TEST(FrameProviders, TestPatternMovesAndHasAConstantDisparity) {
  const auto frames = ws::MovingTestPattern({320, 240});
  const cv::Mat left0 = frames(0, true);
  EXPECT_EQ(left0.size(), cv::Size(320, 240));
  EXPECT_EQ(left0.type(), CV_8UC1);
  EXPECT_GT(cv::norm(left0, frames(1, true), cv::NORM_INF), 0);  // it moves
  EXPECT_EQ(cv::norm(left0, ws::MovingTestPattern({320, 240})(0, true), cv::NORM_INF), 0);
  // The right camera sees the wall 32 pixels further left: right(x) = left(x + 32).
  const cv::Mat right0 = frames(0, false);
  EXPECT_EQ(
      cv::norm(right0(cv::Rect(0, 0, 288, 240)), left0(cv::Rect(32, 0, 288, 240)), cv::NORM_INF),
      0);
  // Moving by 4 pixels per frame: frame 8 is frame 0 shifted by the disparity.
  EXPECT_EQ(cv::norm(frames(8, true), right0, cv::NORM_INF), 0);
}

TEST(FrameProviders, ImagePairServesTheSameTwoFilesAlways) {
  const std::string dir = ws::test::TempDir("pair_frames");
  cv::imwrite(dir + "/l.png", Uniform(10));
  cv::imwrite(dir + "/r.png", Uniform(20));
  const auto frames = ws::MakeFrameProvider("pair:" + dir + "/l.png," + dir + "/r.png", {});
  EXPECT_EQ(frames(0, true).at<uint8_t>(0, 0), 10);
  EXPECT_EQ(frames(5, false).at<uint8_t>(0, 0), 20);
  EXPECT_THROW(ws::ImagePairFrames(dir + "/l.png", dir + "/missing.png"), ws::CameraError);
}

TEST(FrameProviders, DirectoryPairsLeftAndRightByNameInOrder) {
  const std::string dir = ws::test::TempDir("dir_frames");
  cv::imwrite(dir + "/left02.png", Uniform(2));
  cv::imwrite(dir + "/right02.png", Uniform(102));
  cv::imwrite(dir + "/left01.png", Uniform(1));
  cv::imwrite(dir + "/right01.png", Uniform(101));
  std::ofstream(dir + "/notes.txt") << "not an image";
  const auto frames = ws::MakeFrameProvider("dir:" + dir, {});
  EXPECT_EQ(frames(0, true).at<uint8_t>(0, 0), 1);
  EXPECT_EQ(frames(0, false).at<uint8_t>(0, 0), 101);
  EXPECT_EQ(frames(1, false).at<uint8_t>(0, 0), 102);
  EXPECT_EQ(frames(2, true).at<uint8_t>(0, 0), 1);  // over again

  cv::imwrite(dir + "/left03.png", Uniform(3));
  try {
    ws::ImageDirectoryFrames(dir);
    ADD_FAILURE() << "accepted a left image without its right one";
  } catch (const ws::CameraError& e) {
    EXPECT_NE(std::string(e.what()).find("left03.png has no right03.png"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(ws::ImageDirectoryFrames(ws::test::TempDir("empty_frames")), ws::CameraError);
}

TEST(FrameProviders, SpecMustBeKnown) {
  EXPECT_NO_THROW(ws::MakeFrameProvider("pattern", {64, 48}));
  EXPECT_THROW(ws::MakeFrameProvider("video:x.avi", {64, 48}), ws::CameraError);
  EXPECT_THROW(ws::MakeFrameProvider("pair:only-one.png", {64, 48}), ws::CameraError);
}

}  // namespace
