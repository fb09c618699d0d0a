// stereo-health on input it cannot use: scenes without texture give no
// verdict and no refinement, and malformed or unusable messages are counted
// and skipped.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include "health_fixtures.h"
#include "lcm_io/channels.h"
#include "lcm_io/image_codec.h"
#include "rig/rig_file.h"
#include "rig/rig_message.h"
#include "test_support.h"
#include "widestereo/stereo_frame_t.hpp"

namespace {

using namespace ws::test;

const char* kCalibration = "config/calib/sim-default.yaml";  // 1280 x 960

widestereo::stereo_frame_t Frame(const cv::Mat& left, const cv::Mat& right, int64_t id) {
  widestereo::stereo_frame_t frame{};
  frame.utime = 1000000 * (id + 1);
  frame.frame_id = id;
  frame.left = ws::MatToImage(left, frame.utime);
  frame.right = ws::MatToImage(right, frame.utime);
  return frame;
}

cv::Mat Grey(double level, double noise, uint64_t seed) {
  cv::Mat image(960, 1280, CV_8UC1);
  cv::RNG rng(seed);
  rng.fill(image, cv::RNG::NORMAL, level, noise);
  return image;
}

TEST(HealthInput, TexturelessAndBlackScenesAreUnknownAndRefuseRefinement) {
  const std::string dir = TempDir("health-textureless");
  std::vector<LogEvent> events;
  for (int64_t i = 0; i < 4; ++i) {  // sensor noise of 1 and 4 grey levels on a flat grey scene
    const double noise = i < 2 ? 1 : 4;
    events.push_back(Event(ws::channel::kStereoImages, Frame(Grey(128, noise, 2 * i), Grey(128, noise, 2 * i + 1), i)));
  }
  for (int64_t i = 4; i < 7; ++i) {
    const cv::Mat black = cv::Mat::zeros(960, 1280, CV_8UC1);
    events.push_back(Event(ws::channel::kStereoImages, Frame(black, black, i)));
  }
  WriteLog(dir + "/flat.lcmlog", events);
  const HealthRun run = RunHealth(dir, dir + "/flat.lcmlog", kCalibration, "flat", {"--refine"});
  EXPECT_EQ(run.exit_code, 1) << "no refinement from no matches\n" << run.output;
  EXPECT_NE(run.output.find("refinement refused"), std::string::npos) << run.output;
  ASSERT_EQ(run.published.size(), 7u);
  for (const auto& h : run.published) {
    EXPECT_EQ(h.verdict, "unknown") << "frame " << h.frame_id << ": " << h.matches << " matches";
    EXPECT_EQ(h.frames, 0);
  }
  ASSERT_FALSE(run.report.is_null()) << run.output;
  EXPECT_EQ(run.report["verdict"], "unknown");
  EXPECT_FALSE(run.report["refine"]["applied"].get<bool>());
}

TEST(HealthInput, MalformedAndUnusableMessagesAreCountedAndSkipped) {
  const std::string dir = TempDir("health-bad-input");
  const std::vector<uint8_t> garbage = {1, 2, 3, 4, 5, 6, 7, 8, 9};
  widestereo::stereo_calibration_t not_a_rotation = ws::MessageFromRig(ws::StereoRigFromFile(kCalibration), 1);
  not_a_rotation.R[0] = 2;
  widestereo::stereo_calibration_t right_camera_on_the_left = not_a_rotation;  // decodes, cannot rectify
  right_camera_on_the_left.R[0] = 1;
  right_camera_on_the_left.T[0] = 0.3;
  const cv::Mat small = Grey(128, 10, 1);
  std::vector<LogEvent> events = {
      {ws::channel::kStereoImages, garbage},
      {ws::channel::kStereoCalibration, garbage},
      {ws::channel::kStereoCommand, garbage},
      Event(ws::channel::kStereoCalibration, not_a_rotation),
      Event(ws::channel::kStereoCalibration, right_camera_on_the_left),
      Event(ws::channel::kStereoImages, Frame(small(cv::Rect(0, 0, 640, 480)), small(cv::Rect(0, 0, 640, 480)), 0)),
      Event(ws::channel::kStereoCommand, CommandMessage("solve", "stereo-health")),
      Event(ws::channel::kStereoCommand, CommandMessage("refine", "stereo-health", {"now=1"})),
      Event(ws::channel::kStereoCommand, CommandMessage("solve")),  // for every process: not this one's
      Event(ws::channel::kStereoImages, Frame(Grey(128, 1, 5), Grey(128, 1, 6), 1)),
  };
  WriteLog(dir + "/bad.lcmlog", events);
  const HealthRun run = RunHealth(dir, dir + "/bad.lcmlog", kCalibration, "bad");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_EQ(run.published.size(), 1u) << "the one usable frame was checked";
  const auto images = LastCounters(run.out_log, "stereo-health", ws::channel::kStereoImages);
  EXPECT_EQ(images.received, 3);
  EXPECT_EQ(images.rejected, 2) << "garbage, and a frame of another size than the calibration's";
  const auto calibration = LastCounters(run.out_log, "stereo-health", ws::channel::kStereoCalibration);
  EXPECT_EQ(calibration.rejected, 3) << "garbage, R not a rotation, T.x > 0";
  const auto commands = LastCounters(run.out_log, "stereo-health", ws::channel::kStereoCommand);
  EXPECT_EQ(commands.received, 4);
  EXPECT_EQ(commands.rejected, 3) << "garbage, an unknown command for stereo-health, a bad argument";
  EXPECT_EQ(run.report["calibration"], std::string("calibration file ") + kCalibration)
      << "the invalid calibrations replaced nothing";
}

}  // namespace
