// The launcher owns its processes: however it ends (Ctrl-C, SIGTERM from
// systemd, SIGHUP when its terminal closes, its stdout's reader gone, or
// SIGKILL, which it cannot handle at all), no process of the launch outlives
// it, and lcm-logger's log is complete and replays.
#include <signal.h>

#include <chrono>
#include <fstream>

#include <gtest/gtest.h>

#include "launch_fixture.h"
#include "lcm_io/channels.h"
#include "lcm_io/lcm_log.h"
#include "widestereo/stereo_frame_t.hpp"

namespace {

using namespace std::chrono_literals;
using namespace ws::test;

// Running, and not a zombie.
bool Alive(int pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string pid_field, name, state;
  if (!(stat >> pid_field >> name >> state)) return false;
  return state != "Z" && state != "X";
}

int LoggerPid(const std::string& run_dir) {
  const std::string marker = "lcm-logger pid ";
  const std::string log = LaunchLog(run_dir);
  const size_t at = log.find(marker);
  return at == std::string::npos ? -1 : std::stoi(log.substr(at + marker.size()));
}

struct Ending {
  const char* name;
  int signal;  // 0: its stdout's reader goes
};

class LaunchOwnsItsProcesses : public ::testing::TestWithParam<Ending> {};

TEST_P(LaunchOwnsItsProcesses, NoProcessOutlivesTheLauncherAndTheLogIsComplete) {
  const Ending ending = GetParam();
  const std::string run_dir = TempDir(std::string("launch_owns_") + ending.name);
  const std::string url = UniqueUdpmUrl(21) + "&recv_buf_size=16777216";
  ChannelListener images(url, ws::channel::kStereoImages);
  std::vector<std::string> argv =
      LaunchCommand("config/launch/calibrate.yaml", url, run_dir, {"--append", "stereo-capture=--rate=2"});
  if (ending.signal == 0) {  // its stdout a pipe to head, which leaves after the first lines
    std::string line;
    for (const std::string& arg : argv) line += "'" + arg + "' ";
    argv = {"/bin/sh", "-c", line + "| head -n 3 > /dev/null"};
  }
  Command launch(argv);
  std::vector<int> pids;
  for (const char* process : {"stereo-capture", "stereo-detect", "stereo-calibrate"})
    pids.push_back(WaitForStart(run_dir, process, 1, 60s));
  pids.push_back(LoggerPid(run_dir));
  for (int pid : pids) ASSERT_GT(pid, 0) << LaunchLog(run_dir);
  // A broken pipe ends the launch at its first lines; a signal once frames flow.
  if (ending.signal != 0) {
    ASSERT_TRUE(images.Hear(6)) << "no frames on the bus";
    launch.Signal(ending.signal);
  }
  const CommandResult result = launch.Wait(60);
  if (ending.signal != 0 && ending.signal != SIGKILL) {
    EXPECT_EQ(result.exit_code, 0) << result.output;
  }

  PollUntil(30s, [&] {
    for (int pid : pids)
      if (Alive(pid)) return false;
    return true;
  });  // each pid is checked below, named
  for (int pid : pids) EXPECT_FALSE(Alive(pid)) << "pid " << pid << " outlived the launcher\n" << LaunchLog(run_dir);

  const std::string log = run_dir + "/calibrate.lcmlog";
  const ws::LcmLogScan scan = ws::ScanLcmLog(log);
  EXPECT_TRUE(scan.complete()) << scan.problem;
  const auto frames = Messages<widestereo::stereo_frame_t>(ReadLog(log), ws::channel::kStereoImages);
  if (ending.signal != 0) {
    EXPECT_GE(frames.size(), 5u) << "the 6 frames heard on the bus, but one in flight as the launch ended";
  }
  std::printf("%s: launcher ended (code %d); %zu pairs in a complete log\n", ending.name, result.exit_code,
              frames.size());
}

INSTANTIATE_TEST_SUITE_P(EveryWayItEnds, LaunchOwnsItsProcesses,
                         ::testing::Values(Ending{"sigint", SIGINT}, Ending{"sigterm", SIGTERM},
                                           Ending{"sighup", SIGHUP}, Ending{"broken_pipe", 0},
                                           Ending{"sigkill", SIGKILL}),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
