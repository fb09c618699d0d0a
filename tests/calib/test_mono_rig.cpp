// A one-camera rig through the processes: stereo-capture --mono sends a
// folder of one camera's images (opencv-doc's left images) as frames with
// no right image, stereo-detect finds the boards, stereo-calibrate writes a
// calibration of that camera alone.
#include <gtest/gtest.h>

#include <filesystem>

#include "calib/calib_file.h"
#include "calib_process_support.h"
#include "lcm_io/channels.h"
#include "lcm_io/image_codec.h"
#include "widestereo/calibration_status_t.hpp"
#include "widestereo/stereo_corners_t.hpp"
#include "widestereo/stereo_frame_t.hpp"

namespace {

using namespace ws::calib;
using namespace ws::calib::test;
using ws::test::Messages;
using ws::test::ReadLog;

constexpr const char* kBoard = "chessboard:9x6:0.025";

// The opencv-doc left images alone, under names that say nothing of a side.
std::string OneCameraFolder() {
  const std::string dir = ws::test::TempDir("one-camera-images");
  for (const auto& entry : std::filesystem::directory_iterator(ws::test::OpenCvStereoSetDir())) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("left", 0) == 0)
      std::filesystem::create_symlink(std::filesystem::read_symlink(entry.path()),
                                      dir + "/image" + name.substr(4));
  }
  return dir;
}

TEST(MonoRig, AFolderOfOneCamerasImagesCalibratesThatCamera) {
  const std::string dir = ws::test::TempDir("mono-rig");
  const std::string corners =
      CaptureAndDetect(dir, "dir:" + OneCameraFolder(), kBoard, {"--mono", "--frame-clock"});
  const auto frames = Messages<widestereo::stereo_frame_t>(ReadLog(dir + "/images.lcmlog"),
                                                           ws::channel::kStereoImages);
  ASSERT_EQ(frames.size(), 13u);
  for (const auto& frame : frames) {
    EXPECT_TRUE(ws::IsNoImage(frame.right)) << frame.frame_id;
    EXPECT_EQ(frame.left.width, 640);
  }
  const auto found =
      Messages<widestereo::stereo_corners_t>(ReadLog(corners), ws::channel::kStereoCorners);
  ASSERT_EQ(found.size(), 13u);
  for (const auto& c : found) {
    EXPECT_GT(c.left.n, 0) << c.frame_id;
    EXPECT_EQ(c.right.n, 0);
    EXPECT_EQ(c.right.image_width, 0);
  }

  const auto run = CalibrateOnce(dir, corners, "mono", {"--model", "poly6", "--nonradial", "none"});
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const nlohmann::json report = ReadJson(dir + "/mono.json");
  ASSERT_EQ(report["cameras"].size(), 1u);
  EXPECT_EQ(report["cameras"][0]["name"], "left");
  EXPECT_FALSE(report.contains("stereo"));
  const CalibrationFile mono = ReadCalibrationFile(dir + "/mono.yaml");
  EXPECT_TRUE(mono.mono);
  // The status says the camera's RMS, not the empty stereo one.
  const auto statuses = ws::test::Messages<widestereo::calibration_status_t>(
      ws::test::ReadLog(dir + "/mono.lcmlog"), ws::channel::kCalibrationStatus);
  ASSERT_FALSE(statuses.empty());
  EXPECT_EQ(statuses.back().state, "solved");
  EXPECT_NEAR(statuses.back().rms, report["cameras"][0]["rms_px"].get<double>(), 1e-9);

  // The same camera as the left one of the stereo set solved in the paper's
  // flow (each camera from its own views), to the last digits.
  const std::string stereo_dir = ws::test::TempDir("mono-rig-stereo");
  const std::string stereo_corners =
      CaptureAndDetect(stereo_dir, "dir:" + ws::test::OpenCvStereoSetDir(), kBoard);
  const auto stereo_run = CalibrateOnce(stereo_dir, stereo_corners, "stereo",
                                        {"--model", "poly6", "--nonradial", "none", "--flow", "paper"});
  ASSERT_EQ(stereo_run.exit_code, 0) << stereo_run.output;
  const CalibrationFile stereo = ReadCalibrationFile(stereo_dir + "/stereo.yaml");
  EXPECT_EQ(report["cameras"][0]["views"], ReadJson(stereo_dir + "/stereo.json")["cameras"][0]["views"]);
  EXPECT_NEAR(mono.left.fx, stereo.left.fx, 1e-6 * stereo.left.fx);
  EXPECT_NEAR(mono.left.cx, stereo.left.cx, 1e-6 * stereo.left.fx);
  EXPECT_NEAR(mono.left.cy, stereo.left.cy, 1e-6 * stereo.left.fx);
  ASSERT_EQ(mono.left.distortion.coeffs.size(), stereo.left.distortion.coeffs.size());
  for (size_t k = 0; k < mono.left.distortion.coeffs.size(); ++k)
    EXPECT_NEAR(mono.left.distortion.coeffs[k], stereo.left.distortion.coeffs[k], 1e-6) << k;
}

TEST(MonoRig, MonoNeedsAFolder) {
  const std::string dir = ws::test::TempDir("mono-sim");
  const auto r = ws::test::RunCommand({"stereo-capture", "--source", "sim:config/sim/default.yaml",
                                       "--mono", "--log-dir", dir},
                                      30);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("--mono is for dir: sources"), std::string::npos) << r.output;
}

}  // namespace
