// stereo-match --save-rectified DIR [--save-every N]: the rectified pairs
// as PNG files named by frame id, every N-th frame id, holding exactly the
// images that were matched (an identity calibration: the input images).
#include <gtest/gtest.h>

#include <filesystem>

#include <opencv2/imgcodecs.hpp>

#include "lcm_io/channels.h"
#include "lcm_io/image_codec.h"
#include "match/frame_image_writer.h"
#include "match_fixtures.h"
#include "test_support.h"
#include "widestereo/disparity_t.hpp"
#include "widestereo/stereo_frame_t.hpp"

namespace {

using namespace ws::test;

cv::Mat Noise(int seed) {
  cv::Mat image(64, 96, CV_8UC1);
  cv::RNG(seed).fill(image, cv::RNG::UNIFORM, 0, 256);
  return image;
}

TEST(SaveRectified, WritesEveryNthFramesPairAndDisparityNamedByItsFrameId) {
  const std::string dir = TempDir("save-rectified");
  auto calibration = IdentityCalibration(96, 64, 80, 0.1);
  calibration.utime = 1;
  std::vector<LogEvent> events = {Event(ws::channel::kStereoCalibration, calibration)};
  for (int id = 0; id < 5; ++id) {
    widestereo::stereo_frame_t frame{};
    frame.frame_id = id;
    frame.utime = 1000000 * (id + 1);
    frame.left = ws::MatToImage(Noise(2 * id), frame.utime);
    frame.right = ws::MatToImage(Noise(2 * id + 1), frame.utime);
    events.push_back(Event(ws::channel::kStereoImages, frame));
  }
  WriteLog(dir + "/in.lcmlog", events);
  const std::string out = dir + "/rectified";
  const std::string disparities = dir + "/disparity";
  const auto r = RunCommand({"stereo-match", "--log-dir", dir, "--num-disparities", "16", "--save-rectified", out,
                             "--save-disparity", disparities, "--save-every", "2", "--in-url", "file://" + dir + "/in.lcmlog?speed=0",
                             "--out-url", "file://" + dir + "/out.lcmlog?mode=w"},
                            60);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(Messages<widestereo::disparity_t>(ReadLog(dir + "/out.lcmlog"), ws::channel::kStereoDisparity).size(),
            5u);
  for (int id = 0; id < 5; ++id) {
    const std::string left = ws::FrameImagePath(out, "left", id);
    const std::string right = ws::FrameImagePath(out, "right", id);
    EXPECT_EQ(std::filesystem::path(left).filename(), "left_00000" + std::to_string(id) + ".png");
    const std::string disparity = ws::FrameImagePath(disparities, "disparity", id);
    EXPECT_EQ(std::filesystem::exists(disparity), id % 2 == 0) << disparity;
    if (id % 2 == 0) {  // in colour, the legend below the image
      const cv::Mat colour = cv::imread(disparity, cv::IMREAD_UNCHANGED);
      EXPECT_EQ(colour.type(), CV_8UC3) << disparity;
      EXPECT_EQ(colour.cols, 96) << disparity;
      EXPECT_GT(colour.rows, 64) << disparity;
    }
    if (id % 2) {
      EXPECT_FALSE(std::filesystem::exists(left)) << left;
      EXPECT_FALSE(std::filesystem::exists(right)) << right;
      continue;
    }
    const cv::Mat l = cv::imread(left, cv::IMREAD_UNCHANGED), rr = cv::imread(right, cv::IMREAD_UNCHANGED);
    ASSERT_FALSE(l.empty()) << left;
    ASSERT_FALSE(rr.empty()) << right;
    EXPECT_EQ(cv::norm(l, Noise(2 * id), cv::NORM_INF), 0) << left;
    EXPECT_EQ(cv::norm(rr, Noise(2 * id + 1), cv::NORM_INF), 0) << right;
  }
}

TEST(SaveRectified, SaveEveryNeedsAFolderAndAPositiveCount) {
  const std::string dir = TempDir("save-rectified-options");
  auto r = RunCommand({"stereo-match", "--log-dir", dir, "--save-every", "2"}, 30);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("--save-every requires --save-rectified or --save-disparity"), std::string::npos) << r.output;
  r = RunCommand({"stereo-match", "--log-dir", dir, "--save-rectified", dir + "/x", "--save-every", "0"}, 30);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("--save-every"), std::string::npos) << r.output;
}

}  // namespace
