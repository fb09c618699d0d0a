// The launch files pointed at a user's rig without touching the repository:
// a rig file and --set overrides; a process that fails at its start fails
// the launch with its own error on the terminal; recordings are capped.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "launch_fixture.h"
#include "lcm_io/channels.h"
#include "lcm_io/lcm_log.h"
#include "widestereo/disparity_t.hpp"
#include "widestereo/process_status_t.hpp"

namespace {

namespace fs = std::filesystem;
using namespace ws::test;

// `git status` of the repository: what a launch must leave as it was.
std::string TrackedFilesState() {
  return RunCommand({"/usr/bin/git", "-C", SourceDir(), "status", "--porcelain", "--untracked-files=no"}, 30).output;
}

TEST(LaunchRig, RunLaunchOnAFolderAndACalibrationGivenByRigFileAndSet) {
  const std::string dir = TempDir("launch-rig");
  const std::string before = TrackedFilesState();
  // The user's rig, beside its own images and calibration (relative paths).
  fs::create_directories(dir + "/rig1");
  fs::create_directory_symlink(OpenCvStereoSetDir(), dir + "/rig1/scene");
  const CommandResult calibrated =
      RunCommand({"stereo-calibrate", "--images", dir + "/rig1/scene", "--board", "chessboard:9x6:0.025", "--out",
                  dir + "/rig1/calib.yaml", "--model", "poly6"},
                 120);
  ASSERT_EQ(calibrated.exit_code, 0) << calibrated.output;
  std::ofstream(dir + "/rig1/rig.yaml") << "source: dir:scene\ncalibration: calib.yaml\noutput: runs\n";

  const CommandResult r = RunCommand({SourceDir() + "/scripts/launch", SourceDir() + "/config/launch/run.yaml", "--rig",
                                      dir + "/rig1/rig.yaml", "--set", "stereo-capture.rate=4", "--set", "stereo-view.port=0", "--lcm-url",
                                      UniqueUdpmUrl() + "&recv_buf_size=16777216", "--duration", "8"},
                                     120);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // The run folder went under the rig's output folder.
  std::string run_dir;
  for (const auto& entry : fs::recursive_directory_iterator(dir + "/rig1/runs"))
    if (entry.path().filename() == "launch.log") run_dir = entry.path().parent_path().string();
  ASSERT_FALSE(run_dir.empty()) << r.output;
  const std::string record = LaunchLog(run_dir);
  EXPECT_NE(record.find("--source dir:" + dir + "/rig1/scene"), std::string::npos) << record;
  EXPECT_NE(record.find("--rate=4"), std::string::npos) << record;
  EXPECT_EQ(record.find("sim:config/sim/wall.yaml"), std::string::npos) << record;
  EXPECT_NE(record.find("--calib " + dir + "/rig1/calib.yaml"), std::string::npos) << record;
  for (const char* process : {"stereo-capture", "stereo-match", "stereo-cloud", "stereo-health"})
    EXPECT_NE(record.find(std::string(process) + " stopped (code 0)"), std::string::npos) << record;
  // Depth came out of the user's pairs with the user's calibration (in the
  // rolling recording's newest file: 8 s fill less than one).
  EXPECT_GT(Messages<widestereo::disparity_t>(ReadLog(run_dir + "/run.lcmlog.0"), ws::channel::kStereoDisparity).size(),
            0u);
  EXPECT_EQ(TrackedFilesState(), before) << "the launch changed tracked files";
}

TEST(LaunchRig, AProcessThatFailsAtItsStartFailsTheLaunchWithItsOwnError) {
  const std::string run_dir = TempDir("launch-bad-option");
  const CommandResult r =
      RunCommand(LaunchCommand("config/launch/run.yaml", UniqueUdpmUrl(1), run_dir,
                               {"--no-record", "--duration", "60", "--set", "stereo-match.matcher=fastest"}),
                 90);
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("stereo-match failed at its start (code"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("stereo-match: --matcher: fastest not in"), std::string::npos) << r.output;
  // Not the config file's fault, and everything else stopped.
  EXPECT_EQ(r.output.find("stereo-match-live.yaml: --matcher"), std::string::npos) << r.output;
  const std::string record = LaunchLog(run_dir);
  for (const char* process : {"stereo-capture", "stereo-cloud", "stereo-health"})
    EXPECT_NE(record.find(std::string(process) + " stopped"), std::string::npos) << record;
}

TEST(LaunchRig, RecordingStopsAtMaxLogMbAndTheProcessesGoOn) {
  const std::string run_dir = TempDir("launch-cap");
  const CommandResult r = RunCommand(
      LaunchCommand("config/launch/calibrate.yaml", UniqueUdpmUrl(2) + "&recv_buf_size=16777216", run_dir,
                    {"--max-log-mb", "3", "--duration", "6", "--set", "stereo-capture.rate=2"}),
      90);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string record = LaunchLog(run_dir);
  EXPECT_NE(record.find("recording stopped: " + run_dir + "/calibrate.lcmlog reached"), std::string::npos) << record;
  EXPECT_LT(fs::file_size(run_dir + "/calibrate.lcmlog"), 30u * 1000 * 1000);
  EXPECT_NE(record.find("stereo-capture stopped (code 0)"), std::string::npos) << record;
}

// A rolling recording never stops: the newest max_log_mb in ten files
// (each split once past a tenth of it, so one message more at most), each a
// complete log, the oldest deleted; the run launch records so (its
// rolling_log), and stereo-view's heartbeat says how long it spans. Files of
// those names the recording did not write (a reused run folder) are kept.
TEST(LaunchRig, TheRunLaunchKeepsTheNewestMaxLogMbAndNoFileItDidNotWrite) {
  const std::string run_dir = TempDir("launch-rolling");
  const std::string log = run_dir + "/run.lcmlog";
  std::ofstream(log + ".3") << "an earlier launch's";
  const CommandResult r = RunCommand(
      LaunchCommand("config/launch/run.yaml", UniqueUdpmUrl(2) + "&recv_buf_size=16777216", run_dir,
                    {"--max-log-mb", "3", "--duration", "10", "--set", "stereo-capture.rate=3"}),
      90);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string record = LaunchLog(run_dir);
  EXPECT_EQ(record.find("recording stopped"), std::string::npos) << record;
  EXPECT_NE(record.find("a rolling window of the last 3 MB"), std::string::npos) << record;
  EXPECT_NE(record.find("kept " + log + ".3 of an earlier launch as " + log + ".3."), std::string::npos) << record;
  bool kept = false;
  for (const auto& entry : fs::directory_iterator(run_dir))
    if (entry.path().string().rfind(log + ".3.", 0) == 0)
      kept = std::string(std::istreambuf_iterator<char>(std::ifstream(entry.path()).rdbuf()), {}) ==
             "an earlier launch's";
  EXPECT_TRUE(kept) << "the earlier file, moved out of the recording's way";
  EXPECT_TRUE(fs::exists(log + ".9")) << "ten files: <log>.0 to <log>.9";
  EXPECT_FALSE(fs::exists(log + ".10")) << "ten files at most: the oldest deleted";
  EXPECT_FALSE(fs::exists(log));
  bool said_rolling = false;
  for (int i = 0; i <= 9; ++i) {
    const std::string file = log + "." + std::to_string(i);
    if (!fs::exists(file)) continue;
    EXPECT_TRUE(ws::ScanLcmLog(file).complete()) << file;
    EXPECT_LT(fs::file_size(file), 6u * 1000 * 1000) << file << ": 0.3 MB and one message at most";
    for (const auto& status : Messages<widestereo::process_status_t>(ReadLog(file), ws::channel::kProcessStatus))
      said_rolling |= status.name == "stereo-view" && status.state.rfind("recording rolling: the last ", 0) == 0;
  }
  EXPECT_TRUE(said_rolling) << "stereo-view's state: recording rolling: the last N min";
}

}  // namespace
