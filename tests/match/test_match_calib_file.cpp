// stereo-match --calib FILE.yaml: the calibration file starts the process,
// a calibration for another image size is a clear error for every frame
// (counted, not fatal) until a STEREO_CALIBRATION replaces it, and a missing
// or broken file stops the process with the file's name and the reason.
#include <gtest/gtest.h>

#include <fstream>

#include "lcm_io/channels.h"
#include "lcm_io/image_codec.h"
#include "match_fixtures.h"
#include "models/theia_lens.h"
#include "rig/rig_file.h"
#include "test_support.h"
#include "widestereo/disparity_t.hpp"
#include "widestereo/stereo_frame_t.hpp"

namespace {

using namespace ws::test;

widestereo::stereo_frame_t Frame(int64_t frame_id) {
  widestereo::stereo_frame_t frame{};
  frame.frame_id = frame_id;
  frame.utime = 1000000 * (frame_id + 1);
  frame.left = frame.right = ws::MatToImage(cv::Mat(48, 64, CV_8UC1, cv::Scalar(7)), frame.utime);
  return frame;
}

TEST(MatchCalibFile, CalibrationForAnotherImageSizeIsAClearErrorUntilReplaced) {
  const std::string dir = TempDir("match-calib-size");
  ws::Rig rig;  // the 1280 x 960 Theia-like rig
  rig.left = rig.right = ws::TheiaLikeCamera();
  rig.T = Eigen::Vector3d(-0.3, 0, 0);
  const std::string calib = dir + "/calib.yaml";
  WriteCalibrationFile(calib, rig);
  auto message = IdentityCalibration(64, 48, 50, 0.1);
  message.utime = 2500000;
  WriteLog(dir + "/in.lcmlog", {Event(ws::channel::kStereoImages, Frame(0)),
                                Event(ws::channel::kStereoImages, Frame(1)),
                                Event(ws::channel::kStereoCalibration, message),
                                Event(ws::channel::kStereoImages, Frame(2))});
  const auto r = RunCommand({"stereo-match", "--log-dir", dir, "--calib", calib, "--num-disparities", "16",
                             "--in-url", "file://" + dir + "/in.lcmlog?speed=0", "--out-url",
                             "file://" + dir + "/out.lcmlog?mode=w"},
                            60);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // Maps are built as each calibration arrives (from a log, in line), the
  // file's too although none of its frames came.
  EXPECT_NE(r.output.find("using calibration file " + calib + " (1280x960, bspline model)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("rectification maps for calibration file " + calib + " built"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("rectification maps for the STEREO_CALIBRATION"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("frame 0 is 64x48 but calibration file " + calib + " is for 1280x960"),
            std::string::npos)
      << r.output;
  const auto c = LastCounters(dir + "/out.lcmlog", "stereo-match", ws::channel::kStereoImages);
  EXPECT_EQ(c.received, 3);
  EXPECT_EQ(c.rejected, 2);
  const auto disparities =
      Messages<widestereo::disparity_t>(ReadLog(dir + "/out.lcmlog"), ws::channel::kStereoDisparity);
  ASSERT_EQ(disparities.size(), 1u);
  EXPECT_EQ(disparities[0].frame_id, 2);
}

TEST(MatchCalibFile, MissingOrBrokenFileStopsTheProcessNamingIt) {
  const std::string dir = TempDir("match-calib-bad");
  auto r = RunCommand({"stereo-match", "--log-dir", dir, "--calib", dir + "/none.yaml"}, 30);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find(dir + "/none.yaml"), std::string::npos) << r.output;

  ws::Rig rig;
  rig.left = rig.right = ws::TheiaLikeCamera();
  rig.T = Eigen::Vector3d(-0.3, 0, 0);
  const std::string good = dir + "/good.yaml";
  WriteCalibrationFile(good, rig);
  std::ifstream in(good);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const size_t width = text.find("image_width");
  ASSERT_NE(width, std::string::npos);
  text.replace(width, std::string("image_width").size(), "image_wide");
  const std::string broken = dir + "/broken.yaml";
  std::ofstream(broken) << text;
  r = RunCommand({"stereo-match", "--log-dir", dir, "--calib", broken}, 30);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("stereo-match: " + broken + ": left"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("image_width"), std::string::npos) << r.output;
}

}  // namespace
