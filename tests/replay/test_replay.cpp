// Replay determinism (issue #7): the same recorded log through stereo-detect
// and stereo-calibrate gives the same outputs every time, and replaying the
// corners live (lcm-logplayer over udpm) gives the calibration the batch
// replay gives.
#include <signal.h>

#include <filesystem>
#include <thread>

#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>

#include "lcm_io/channels.h"
#include "test_support.h"
#include "widestereo/calibration_status_t.hpp"

namespace {

using namespace std::chrono_literals;
using namespace ws::test;

// The payloads on `channel`, in order (PROCESS_STATUS carries wall-clock
// uptime, host and pid, so whole logs are compared channel by channel).
std::vector<std::vector<uint8_t>> Payloads(const std::string& log, const std::string& channel) {
  std::vector<std::vector<uint8_t>> out;
  for (const LogEvent& e : ReadLog(log))
    if (e.channel == channel) out.push_back(e.data);
  return out;
}

std::string FileUrl(const std::string& path, const std::string& query) { return "file://" + path + "?" + query; }

// The views a stereo-calibrate status counts.
struct ViewCounts {
  int left = -1, right = -1, stereo = -1;
  bool operator==(const ViewCounts& o) const { return left == o.left && right == o.right && stereo == o.stereo; }
};

ViewCounts CountsOf(const widestereo::calibration_status_t& s) { return {s.views_left, s.views_right, s.views_stereo}; }

// The last CALIBRATION_STATUS heard on a bus.
struct StatusListener {
  explicit StatusListener(const std::string& url) : lcm(url) {
    lcm.subscribeFunction(
        ws::channel::kCalibrationStatus,
        +[](const lcm::ReceiveBuffer*, const std::string&, const widestereo::calibration_status_t* s,
            StatusListener* self) {
          self->last = CountsOf(*s);
          ++self->heard;
        },
        this);
  }
  bool Until(double seconds, const std::function<bool()>& done) { return HandleUntil(lcm, seconds, done); }
  lcm::LCM lcm;
  ViewCounts last;
  int heard = 0;
};

struct Outputs {
  std::string corners_log, calibration_log, calibration_file;
};

// stereo-detect then stereo-calibrate --once, as log-to-log filters.
Outputs DetectAndCalibrate(const std::string& images_log, const std::string& dir) {
  Outputs out{dir + "/corners.lcmlog", dir + "/calibration.lcmlog", dir + "/calibration.yaml"};
  const CommandResult detect =
      RunCommand({"stereo-detect", "--board", "chessboard:9x6:0.05", "--in-url", FileUrl(images_log, "speed=0"),
                  "--out-url", FileUrl(out.corners_log, "mode=w"), "--log-dir", dir, "--quiet"},
                 120);
  EXPECT_EQ(detect.exit_code, 0) << detect.output;
  const CommandResult calibrate =
      RunCommand({"stereo-calibrate", "--once", "--in-url", FileUrl(out.corners_log, "speed=0"), "--out-url",
                  FileUrl(out.calibration_log, "mode=w"), "--out", out.calibration_file, "--log-dir", dir, "--quiet"},
                 180);
  EXPECT_EQ(calibrate.exit_code, 0) << calibrate.output;
  return out;
}

TEST(Replay, TheSameLogGivesTheSameCornersAndCalibrationEveryTime) {
  const std::string images = SourceDir() + "/logs/sim-images.lcmlog";
  const Outputs first = DetectAndCalibrate(images, TempDir("replay_first"));
  const Outputs second = DetectAndCalibrate(images, TempDir("replay_second"));
  const auto corners = Payloads(first.corners_log, ws::channel::kStereoCorners);
  EXPECT_EQ(corners.size(), 30u);
  EXPECT_EQ(corners, Payloads(second.corners_log, ws::channel::kStereoCorners));
  const auto calibration = Payloads(first.calibration_log, ws::channel::kStereoCalibration);
  EXPECT_EQ(calibration.size(), 1u);
  EXPECT_EQ(calibration, Payloads(second.calibration_log, ws::channel::kStereoCalibration));
  EXPECT_EQ(Payloads(first.calibration_log, ws::channel::kCalibrationStatus),
            Payloads(second.calibration_log, ws::channel::kCalibrationStatus));
  EXPECT_FALSE(ReadFileText(first.calibration_file).empty());
  EXPECT_EQ(ReadFileText(first.calibration_file), ReadFileText(second.calibration_file));
}

TEST(Replay, LiveReplayOfTheCornersGivesTheBatchCalibration) {
  const std::string corners = SourceDir() + "/logs/sim-corners.lcmlog";
  const std::string dir = TempDir("replay_live");
  const std::string url = UniqueUdpmUrl();
  const std::string live_file = dir + "/live.yaml";
  const std::string batch_file = dir + "/batch.yaml";
  const CommandResult batch =
      RunCommand({"stereo-calibrate", "--once", "--in-url", FileUrl(corners, "speed=0"), "--out-url",
                  FileUrl(dir + "/batch.lcmlog", "mode=w"), "--out", batch_file, "--log-dir", dir, "--quiet"},
                 180);
  ASSERT_EQ(batch.exit_code, 0) << batch.output;
  const auto batch_statuses =
      Messages<widestereo::calibration_status_t>(ReadLog(dir + "/batch.lcmlog"), ws::channel::kCalibrationStatus);
  ASSERT_FALSE(batch_statuses.empty());
  const ViewCounts every_view = CountsOf(batch_statuses.back());

  StatusListener bus(url);
  Command calibrate({"stereo-calibrate", "--in-url", url, "--out-url", url, "--out", live_file, "--state",
                     dir + "/state.yaml", "--log-dir", dir, "--quiet"});
  // Its first status: it is subscribed before the first corners are played.
  ASSERT_TRUE(bus.Until(30, [&] { return bus.heard > 0; })) << calibrate.Output();
  const CommandResult player = RunCommand({"lcm-logplayer", "--speed=4", "--lcm-url=" + url, corners}, 120);
  ASSERT_EQ(player.exit_code, 0) << player.output;
  // Solved once it holds every view the batch run took.
  ASSERT_TRUE(bus.Until(60, [&] { return bus.last == every_view; }))
      << "views " << bus.last.left << "/" << bus.last.right << "/" << bus.last.stereo << ", the batch run's "
      << every_view.left << "/" << every_view.right << "/" << every_view.stereo;
  const CommandResult solve = RunCommand({"stereo-command", "solve", "--out-url", url, "--log-dir", dir, "--quiet"});
  ASSERT_EQ(solve.exit_code, 0) << solve.output;
  for (int i = 0; i < 1200 && !std::filesystem::exists(live_file); ++i) std::this_thread::sleep_for(100ms);
  calibrate.Signal(SIGINT);
  EXPECT_EQ(calibrate.Wait(60).exit_code, 0);
  ASSERT_TRUE(std::filesystem::exists(live_file)) << calibrate.Output();
  EXPECT_EQ(ReadFileText(live_file), ReadFileText(batch_file));
}

}  // namespace
