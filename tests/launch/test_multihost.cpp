// Two hosts on one machine: Linux network namespaces joined by a veth pair.
// The robot namespace captures (the simulator, JPEG), the compute namespace
// detects and calibrates, over udpm with ttl=1 (config/launch/robot-network.yaml).
#include <unistd.h>

#include <filesystem>
#include <functional>
#include <optional>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "launch_fixture.h"
#include "lcm_io/channels.h"
#include "runtime/wall_clock.h"
#include "widestereo/process_status_t.hpp"

namespace {

using namespace std::chrono_literals;
using namespace ws::test;

// Two namespaces "<prefix>-robot" and "<prefix>-compute", 10.77.0.1 and
// 10.77.0.2 on a veth pair, multicast routed onto it; removed on destruction.
class TwoHosts {
 public:
  TwoHosts() : prefix_("ws" + std::to_string(getpid())) {
    const std::string robot = Namespace("robot"), compute = Namespace("compute");
    const std::string veth_robot = prefix_ + "r", veth_compute = prefix_ + "c";
    for (const std::vector<std::string>& step : std::vector<std::vector<std::string>>{
             {"ip", "netns", "add", robot},
             {"ip", "netns", "add", compute},
             {"ip", "link", "add", veth_robot, "type", "veth", "peer", "name", veth_compute},
             {"ip", "link", "set", veth_robot, "netns", robot},
             {"ip", "link", "set", veth_compute, "netns", compute},
             {"ip", "-n", robot, "addr", "add", "10.77.0.1/24", "dev", veth_robot},
             {"ip", "-n", compute, "addr", "add", "10.77.0.2/24", "dev", veth_compute},
             {"ip", "-n", robot, "link", "set", veth_robot, "up"},
             {"ip", "-n", compute, "link", "set", veth_compute, "up"},
             {"ip", "-n", robot, "link", "set", "lo", "up"},
             {"ip", "-n", compute, "link", "set", "lo", "up"},
             {"ip", "-n", robot, "route", "add", "224.0.0.0/4", "dev", veth_robot},
             {"ip", "-n", compute, "route", "add", "224.0.0.0/4", "dev", veth_compute}}) {
      const CommandResult result = RunCommand(step, 20);
      if (result.exit_code != 0) {
        error_ = "'" + step[0] + " " + step[1] + " " + step[2] + " ...' failed: " + result.output;
        return;
      }
    }
  }
  ~TwoHosts() {
    for (const char* host : {"robot", "compute"}) RunCommand({"ip", "netns", "del", Namespace(host)}, 20);
  }

  const std::string& error() const { return error_; }
  std::string Namespace(const std::string& host) const { return prefix_ + "-" + host; }
  // argv run inside the namespace of `host`.
  std::vector<std::string> In(const std::string& host, std::vector<std::string> argv) const {
    argv.insert(argv.begin(), {"ip", "netns", "exec", Namespace(host)});
    return argv;
  }

 private:
  std::string prefix_;
  std::string error_;
};

// The newest counters of `channel` that `process` reported (PROCESS_STATUS)
// in the recording of the launch in `run_dir` in a status stamped after
// `after` (wall-clock microseconds); nullopt before there is one.
std::optional<widestereo::channel_counters_t> Reported(const std::string& run_dir, const std::string& process,
                                                       const std::string& channel, int64_t after = 0) {
  for (const auto& entry : std::filesystem::directory_iterator(run_dir)) {
    if (entry.path().extension() != ".lcmlog") continue;
    const auto statuses =
        Messages<widestereo::process_status_t>(ReadLog(entry.path().string()), ws::channel::kProcessStatus);
    for (auto s = statuses.rbegin(); s != statuses.rend(); ++s)
      if (s->name == process && s->utime > after)
        for (const auto& c : s->channels)
          if (c.channel == channel) return c;
  }
  return std::nullopt;
}

TEST(MultiHost, CaptureOnOneHostCalibrationOnTheOther) {
  TwoHosts hosts;
  if (!hosts.error().empty()) GTEST_SKIP() << "network namespaces unavailable here: " << hosts.error();
  const std::string url = "udpm://239.255.76.67:7667?ttl=1&recv_buf_size=16777216";
  const std::string robot_dir = TempDir("multihost_robot"), compute_dir = TempDir("multihost_compute");
  constexpr int kFrames = 35;  // captured on the robot

  // The compute host records its bus: the processes' own counters say when
  // they listen and when the last frame has gone through.
  Command compute(hosts.In("compute", LaunchCommand("config/launch/robot-network.yaml", url, compute_dir,
                                                    {"--host", "compute"})));
  ASSERT_GT(WaitForStart(compute_dir, "stereo-calibrate", 1, 60s), 0);
  ASSERT_TRUE(PollUntil(60s, [&] {
    return Reported(compute_dir, "stereo-detect", ws::channel::kStereoImages) &&
           Reported(compute_dir, "stereo-calibrate", ws::channel::kStereoCorners);
  })) << "stereo-detect and stereo-calibrate reported no subscription\n" << LaunchLog(compute_dir);
  const CommandResult robot = RunCommand(
      hosts.In("robot", LaunchCommand("config/launch/robot-network.yaml", url, robot_dir,
                                      {"--host", "robot", "--no-record", "--append", "stereo-capture=--count=" + std::to_string(kFrames),
                                       "--append", "stereo-capture=--rate=3"})),
      300);
  ASSERT_EQ(robot.exit_code, 0) << robot.output;
  EXPECT_NE(LaunchLog(robot_dir).find("stereo-capture finished (code 0)"), std::string::npos) << LaunchLog(robot_dir);
  // Counted after the robot's last frame: every frame stereo-detect received
  // handled, and its corners with the calibrator.
  const int64_t sent = ws::WallMicros();
  EXPECT_TRUE(PollUntil(60s, [&] {
    const auto images = Reported(compute_dir, "stereo-detect", ws::channel::kStereoImages, sent);
    const auto corners = Reported(compute_dir, "stereo-detect", ws::channel::kStereoCorners, sent);
    const auto taken = Reported(compute_dir, "stereo-calibrate", ws::channel::kStereoCorners, sent);
    return images && corners && taken && images->received > 0 &&
           corners->published + images->dropped + images->skipped + images->rejected >= images->received &&
           taken->received >= corners->published;
  })) << "the frames did not all reach the calibrator\n" << LaunchLog(compute_dir);

  const CommandResult solve = RunCommand(hosts.In("compute", {BinDir() + "/stereo-command", "solve", "--out-url", url,
                                                              "--log-dir", compute_dir, "--quiet"}),
                                         30);
  ASSERT_EQ(solve.exit_code, 0) << solve.output;
  const std::string calibration = compute_dir + "/calibration.yaml";
  PollUntil(60s, [&] { return std::filesystem::exists(calibration); });  // asserted once the launch is stopped
  compute.Signal(SIGINT);
  EXPECT_EQ(compute.Wait(60).exit_code, 0);
  ASSERT_TRUE(std::filesystem::exists(calibration)) << LaunchLog(compute_dir);

  cv::FileStorage file(calibration, cv::FileStorage::READ);
  cv::Mat T;
  file["stereo"]["T"] >> T;
  ASSERT_EQ(T.total(), 3u);
  EXPECT_NEAR(cv::norm(T), 0.3, 0.003) << "the simulated rig's baseline";
}

}  // namespace
