// The calibrate launch on the simulator, as a user runs it: a process that
// dies is restarted without a gap in the other channels, one stopped by a
// signal from outside is reported as stopped, and Ctrl-C leaves a complete
// log that replays.
#include <signal.h>
#include <sys/stat.h>

#include <algorithm>
#include <fstream>

#include <gtest/gtest.h>

#include "auth/rig_key.h"
#include "launch_fixture.h"
#include "lcm_io/channels.h"
#include "lcm_io/lcm_log.h"
#include "widestereo/calibration_status_t.hpp"
#include "widestereo/stereo_corners_t.hpp"
#include "widestereo/stereo_frame_t.hpp"

namespace {

using namespace std::chrono_literals;
using namespace ws::test;

// Frame ids of the messages, in log order.
template <class Msg>
std::vector<int64_t> FrameIds(const std::vector<LogEvent>& events, const std::string& channel) {
  std::vector<int64_t> ids;
  for (const Msg& m : Messages<Msg>(events, channel)) ids.push_back(m.frame_id);
  return ids;
}

TEST(Launch, RestartsAKilledProcessAndCtrlCLeavesACompleteReplayableLog) {
  const std::string run_dir = TempDir("launch_calibrate");
  const std::string url = UniqueUdpmUrl() + "&recv_buf_size=16777216";
  ChannelListener detector(url, ws::channel::kStereoCorners);
  Command launch(LaunchCommand("config/launch/calibrate.yaml", url, run_dir, {"--append", "stereo-capture=--rate=2"}));
  const int detect = WaitForStart(run_dir, "stereo-detect", 1, 60s);
  ASSERT_GT(detect, 0);
  // Past the launcher's startup window (scripts/launch STARTUP_S, 5 s): a
  // process that dies sooner fails the launch instead of being restarted.
  ASSERT_TRUE(detector.Hear(3, std::chrono::steady_clock::now() + 6s)) << "the detector published no corners";
  kill(detect, SIGKILL);
  ASSERT_GT(WaitForStart(run_dir, "stereo-detect", 2, 30s), 0);
  ASSERT_TRUE(detector.Hear(4)) << "the restarted detector published no corners";
  // stereo-capture stopped by a SIGTERM not from the launch exits 0, as on
  // Ctrl-C: the launch says it was stopped, not that it finished.
  const int capture = WaitForStart(run_dir, "stereo-capture", 1, 5s);
  ASSERT_GT(capture, 0);
  kill(capture, SIGTERM);
  EXPECT_TRUE(PollUntil(30s, [&] {
    return LaunchLog(run_dir).find("stereo-capture was STOPPED (code 0)") != std::string::npos;
  })) << LaunchLog(run_dir);
  launch.Signal(SIGINT);
  const CommandResult result = launch.Wait(60);
  ASSERT_EQ(result.exit_code, 0) << result.output;

  const std::string record = LaunchLog(run_dir);
  EXPECT_NE(record.find("stereo-detect died (signal 9); restarting (1 of 3)"), std::string::npos) << record;
  EXPECT_NE(record.find("stereo-capture was STOPPED (code 0) by a signal from outside this launch"), std::string::npos)
      << record;
  EXPECT_EQ(record.find("stereo-capture finished"), std::string::npos) << record;
  for (const char* process : {"stereo-detect", "stereo-calibrate"})
    EXPECT_NE(record.find(std::string(process) + " stopped (code 0)"), std::string::npos) << record;

  const std::string log = run_dir + "/calibrate.lcmlog";
  const ws::LcmLogScan scan = ws::ScanLcmLog(log);
  EXPECT_TRUE(scan.complete()) << scan.problem;
  const std::vector<LogEvent> events = ReadLog(log);
  const auto images = FrameIds<widestereo::stereo_frame_t>(events, ws::channel::kStereoImages);
  ASSERT_GE(images.size(), 7u) << "the images of both detectors' corners";
  for (const auto& frame : Messages<widestereo::stereo_frame_t>(events, ws::channel::kStereoImages))
    EXPECT_TRUE(frame.left.pixelformat == widestereo::image_t::PIXEL_FORMAT_PNG &&
                frame.right.pixelformat == widestereo::image_t::PIXEL_FORMAT_PNG)
        << "the calibrate launch records its images PNG (lossless), so that a session fits under its cap";
  for (size_t i = 1; i < images.size(); ++i)
    EXPECT_EQ(images[i], images[i - 1] + 1) << "STEREO_IMAGES lost frames while stereo-detect restarted";

  // Corners before the kill and after the restart, and a gap between.
  const auto corners = FrameIds<widestereo::stereo_corners_t>(events, ws::channel::kStereoCorners);
  ASSERT_FALSE(corners.empty());
  size_t restart = 0;  // the first corners of the restarted detector
  for (size_t i = 1; i < corners.size() && restart == 0; ++i)
    if (corners[i] != corners[i - 1] + 1) restart = i;
  ASSERT_GT(restart, 0u) << "the killed detector's frames are missing";
  EXPECT_GE(corners.size() - restart, 3u) << "the restarted detector published corners";
  EXPECT_GE(Messages<widestereo::calibration_status_t>(events, ws::channel::kCalibrationStatus).size(), 3u);

  // It replays: stereo-detect over the recorded images gives corners for all of them.
  const std::string replay = TempDir("launch_replay") + "/corners.lcmlog";
  const CommandResult detected = RunCommand({"stereo-detect", "--board", "chessboard:9x6:0.05", "--in-url",
                                             "file://" + log + "?speed=0", "--out-url", "file://" + replay + "?mode=w",
                                             "--log-dir", TempDir("launch_replay_logs"), "--quiet"},
                                            120);
  ASSERT_EQ(detected.exit_code, 0) << detected.output;
  EXPECT_EQ(FrameIds<widestereo::stereo_corners_t>(ReadLog(replay), ws::channel::kStereoCorners), images);
}

// A launch file's key_file reaches every process as --key-file; a key that
// others may read stops the process at its start, saying why.
TEST(Launch, GivesEveryProcessTheKeyFile) {
  const std::string dir = TempDir("launch_key");
  const std::string key = WriteKeyFile(dir, "rig.key");
  const std::string launch_file = dir + "/keyed.yaml";
  std::ofstream(launch_file) << "description: one signed command\nkey_file: " << key
                             << "\nrecord: false\nprocesses:\n  - name: stereo-command\n    args: [solve]\n"
                                "    restarts: 0\n";
  auto launch = [&](const std::string& run_dir, int exit_code) {
    const CommandResult r = RunCommand(
        {SourceDir() + "/scripts/launch", launch_file, "--lcm-url", UniqueUdpmUrl(2), "--run-dir", run_dir}, 60);
    EXPECT_EQ(r.exit_code, exit_code) << r.output;
    return LaunchLog(run_dir);
  };
  std::string record = launch(dir + "/keyed", 0);
  EXPECT_NE(record.find("rig key " + key + ": commands and calibrations are signed and checked"), std::string::npos)
      << record;
  EXPECT_NE(record.find(" --key-file " + key), std::string::npos) << record;
  EXPECT_NE(record.find("stereo-command finished (code 0)"), std::string::npos) << record;
  EXPECT_NE(ReadFileText(dir + "/keyed/stereo-command.log").find("rig key " + ws::auth::RigKey::FromFile(key).IdText()),
            std::string::npos);

  chmod(key.c_str(), 0644);
  record = launch(dir + "/shared", 1);  // it fails at its start: so does the launch
  EXPECT_NE(record.find("stereo-command failed at its start (code 1)"), std::string::npos) << record;
  EXPECT_NE(ReadFileText(dir + "/shared/stereo-command.out").find("mode 0644 lets others read or change it"),
            std::string::npos);
}

}  // namespace
