// Live over udpm (issue #17): stereo-match and stereo-health start from a
// calibration whose right camera is pitched by 0.2 deg; stereo-health says
// misaligned; a `refine` command makes it publish the corrected
// STEREO_CALIBRATION, which stereo-match rebuilds its maps from, and after
// which stereo-health itself says ok.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <functional>
#include <set>

#include <lcm/lcm-cpp.hpp>

#include "health_fixtures.h"
#include "lcm_io/channels.h"
#include "match_fixtures.h"
#include "rig/rig_file.h"
#include "rig/rig_message.h"
#include "sim/ground_truth.h"
#include "test_support.h"
#include "widestereo/process_status_t.hpp"
#include "widestereo/stereo_frame_t.hpp"

namespace {

using namespace ws::test;

// What the processes say on the bus. Function subscriptions: LCM 1.3.1's
// member-function ones trip UBSan's alignment check in make test-asan.
struct Bus {
  explicit Bus(const std::string& url) : lcm(url) {
    lcm.subscribeFunction(
        ws::channel::kCalibrationHealth,
        +[](const lcm::ReceiveBuffer*, const std::string&, const widestereo::calibration_health_t* h, Bus* bus) {
          bus->health.push_back(*h);
        },
        this);
    lcm.subscribeFunction(
        ws::channel::kStereoCalibration,
        +[](const lcm::ReceiveBuffer*, const std::string&, const widestereo::stereo_calibration_t* c, Bus* bus) {
          bus->calibrations.push_back(*c);
        },
        this);
    lcm.subscribeFunction(
        ws::channel::kProcessStatus,
        +[](const lcm::ReceiveBuffer*, const std::string&, const widestereo::process_status_t* s, Bus* bus) {
          bus->heard.insert(s->name);
        },
        this);
  }
  bool Until(double seconds, const std::function<bool()>& done) { return ws::test::HandleUntil(lcm, seconds, done); }
  lcm::LCM lcm;
  std::vector<widestereo::calibration_health_t> health;
  std::vector<widestereo::stereo_calibration_t> calibrations;
  std::set<std::string> heard;
};

TEST(HealthLive, RefineCommandRepairsTheCalibrationAndStereoMatchRebuildsItsMaps) {
  const std::string dir = TempDir("health-live");
  RenderScene("config/sim/wall.yaml", 3, dir, "wall");
  const ws::Rig truth = ws::LoadSimTruth(dir + "/wall.truth.yaml").rig;
  const std::string calib = dir + "/pitched.yaml";
  WriteCalibrationFile(calib, RightCameraTurned(truth, Eigen::Vector3d::UnitX(), 0.2));
  const auto frames = Messages<widestereo::stereo_frame_t>(ReadLog(dir + "/wall.lcmlog"), ws::channel::kStereoImages);
  ASSERT_EQ(frames.size(), 3u);

  // A 2.4 MB pair is 40 UDP fragments: a receive buffer that holds it.
  const std::string url = UniqueUdpmUrl(17) + "&recv_buf_size=4194304";
  Bus bus(url);
  ASSERT_TRUE(bus.lcm.good());
  Command match({"stereo-match", "--config", "config/stereo-match.yaml", "--calib", calib, "--in-url", url,
                 "--out-url", url, "--log-dir", dir, "--quiet"});
  Command health({"stereo-health", "--config", "config/stereo-health.yaml", "--calib", calib, "--period", "0",
                  "--in-url", url, "--out-url", url, "--log-dir", dir, "--quiet"});
  ASSERT_TRUE(bus.Until(15, [&] { return bus.heard.count("stereo-match") && bus.heard.count("stereo-health"); }))
      << match.Output() << health.Output();

  int64_t id = 0;
  auto send_until = [&](const std::function<bool()>& done) {
    for (int i = 0; i < 20 && !done(); ++i) {
      widestereo::stereo_frame_t frame = frames[size_t(id % 3)];
      frame.frame_id = id++;
      bus.lcm.publish(ws::channel::kStereoImages, &frame);
      bus.Until(0.5, done);
    }
    return done();
  };
  ASSERT_TRUE(send_until([&] { return !bus.health.empty() && bus.health.back().verdict == "misaligned"; }))
      << health.Output();
  EXPECT_GE(bus.health.back().dy_median_px, 0.5);

  const widestereo::command_t refine = CommandMessage("refine", "stereo-health");
  bus.lcm.publish(ws::channel::kStereoCommand, &refine);
  ASSERT_TRUE(bus.Until(10, [&] { return !bus.calibrations.empty(); })) << health.Output();
  const ws::Rig refined = ws::RigFromMessage(bus.calibrations.back());
  EXPECT_LE(RotationAngleDeg(refined.R, truth.R), 0.02);

  // And stereo-health, now measuring through it, says ok.
  const size_t before = bus.health.size();
  EXPECT_TRUE(send_until([&] { return bus.health.size() > before && bus.health.back().verdict == "ok"; }));
  EXPECT_LE(bus.health.back().dy_median_px, 0.15);

  // stereo-match rebuilt its maps from that very message, for the frames after it.
  const std::string rebuilt =
      "rectification maps for the STEREO_CALIBRATION of utime " + std::to_string(bus.calibrations.back().utime);
  const bool heard = bus.Until(15, [&] { return ReadFileText(dir + "/stereo-match.log").find(rebuilt) != std::string::npos; });
  EXPECT_TRUE(heard) << ReadFileText(dir + "/stereo-match.log");

  match.Signal(SIGINT);
  health.Signal(SIGINT);
  EXPECT_EQ(match.Wait(30).exit_code, 0);
  EXPECT_EQ(health.Wait(30).exit_code, 0);
}

}  // namespace
