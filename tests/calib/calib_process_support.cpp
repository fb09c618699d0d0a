#include "calib_process_support.h"

#include <gtest/gtest.h>

#include <fstream>

#include "calib/node/corners_message.h"
#include "lcm_io/channels.h"
#include "widestereo/stereo_corners_t.hpp"

namespace ws::calib::test {

std::string FileUrl(const std::string& path, const std::string& mode) {
  return "file://" + path + "?" + mode;
}

std::string CaptureAndDetect(const std::string& dir, const std::string& source,
                             const std::string& board, const std::vector<std::string>& extra) {
  const std::string images = dir + "/images.lcmlog", corners = dir + "/corners.lcmlog";
  std::vector<std::string> capture = {
      "stereo-capture",         "--source", source, "--log-dir", dir, "--quiet", "--out-url",
      FileUrl(images, "mode=w")};
  capture.insert(capture.end(), extra.begin(), extra.end());
  const auto captured = ws::test::RunCommand(capture, 120);
  EXPECT_EQ(captured.exit_code, 0) << captured.output;
  const auto detected = ws::test::RunCommand(
      {"stereo-detect", "--board", board, "--log-dir", dir, "--quiet", "--in-url",
       FileUrl(images, "speed=0"), "--out-url", FileUrl(corners, "mode=w")},
      120);
  EXPECT_EQ(detected.exit_code, 0) << detected.output;
  return corners;
}

ws::test::CommandResult CalibrateOnce(const std::string& dir, const std::string& corners,
                                      const std::string& name, std::vector<std::string> extra) {
  std::vector<std::string> argv = {"stereo-calibrate",
                                   "--once",
                                   "--log-dir",
                                   dir,
                                   "--in-url",
                                   FileUrl(corners, "speed=0"),
                                   "--out-url",
                                   FileUrl(dir + "/" + name + ".lcmlog", "mode=w"),
                                   "--out",
                                   dir + "/" + name + ".yaml",
                                   "--report",
                                   dir + "/" + name + ".json"};
  argv.insert(argv.end(), extra.begin(), extra.end());
  return ws::test::RunCommand(argv, 120);
}

StereoData ReadCorners(const std::string& corners_log) {
  StereoData data;
  for (const auto& msg : ws::test::Messages<widestereo::stereo_corners_t>(
           ws::test::ReadLog(corners_log), channel::kStereoCorners))
    AddStereoCorners(data, msg);
  return data;
}

nlohmann::json ReadJson(const std::string& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << path;
  return nlohmann::json::parse(in);
}

}  // namespace ws::calib::test
