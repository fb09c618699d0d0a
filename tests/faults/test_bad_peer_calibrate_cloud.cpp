// The bad peer (bad_peer.h) against stereo-calibrate and stereo-cloud: every
// channel each reads, STEREO_COMMAND included, is flooded while the good
// messages flow over udpm. Each keeps running, counts every bad message as
// rejected, and gives what a clean replay of the good messages gives: the
// same calibration file, the same filtered clouds; with a rig key and without.
#include <gtest/gtest.h>
#include <signal.h>

#include <cmath>
#include <filesystem>

#include "bad_peer.h"
#include "cloud_test_support.h"
#include "lcm_io/channels.h"
#include "widestereo/point_cloud_t.hpp"
#include "widestereo/stereo_corners_t.hpp"

namespace {

using namespace ws::test;
namespace ch = ws::channel;

TEST_P(BadPeer, StereoCalibrateRejectsItAllAndSolvesTheSame) {
  const std::string dir = TempDir("faults-calibrate");
  std::vector<LogEvent> corners;
  for (const LogEvent& e : ReadLog(SourceDir() + "/logs/sim-corners.lcmlog"))
    if (e.channel == ch::kStereoCorners) corners.push_back(e);
  ASSERT_EQ(corners.size(), 30u);
  const std::string clean_file = dir + "/clean.yaml", live_file = dir + "/live.yaml";
  CleanRun(dir, corners, {"stereo-calibrate", "--once", "--out", clean_file}, ch::kStereoCalibration);
  ASSERT_TRUE(std::filesystem::exists(clean_file));

  const std::string url = UniqueUdpmUrl(14) + "&recv_buf_size=8388608";
  std::vector<std::string> argv = {"stereo-calibrate", "--out", live_file, "--state", "none", "--log-dir", dir,
                                   "--in-url", url, "--out-url", url};
  for (const std::string& arg : KeyArgs(dir)) argv.push_back(arg);
  Command process(argv);
  BusWatch bus(url, "stereo-calibrate");
  bus.Collect(ch::kStereoCalibration);
  ASSERT_TRUE(bus.ListenUntil(20, [&] { return bus.status().has_value(); })) << process.Output();

  widestereo::stereo_corners_t first;
  ASSERT_GT(first.decode(corners[0].data.data(), 0, int(corners[0].data.size())), 0);
  auto not_finite = first;
  not_finite.left.image_points[0][0] = std::nan("");
  BadChannel bad_corners{ch::kStereoCorners, BadMessages(corners[0].data, Encoded(CommandMessage("solve", "")),
                                                         Encoded(not_finite), 10)};
  // Unknown commands and bad arguments sent to stereo-calibrate are refused.
  const auto bad_argument = CommandMessage("solve", "stereo-calibrate", {"knots=1000"});
  BadChannel bad_commands{ch::kStereoCommand,
                          BadMessages(Encoded(CommandMessage("solve", "stereo-calibrate")), corners[0].data,
                                      Encoded(CommandMessage("frobnicate", "stereo-calibrate")), 11)};
  const std::vector<BadChannel*> both = {&bad_corners, &bad_commands};
  for (size_t i = 0; i < corners.size(); ++i) {
    if (i % 6 == 0) Flood(bus, both);
    bus.Publish(ch::kStereoCorners,
                AsSent(ch::kStereoCorners, ws::DecodeMessage<widestereo::stereo_corners_t>(corners[i].data.data(),
                                                                                           int(corners[i].data.size()))));
    bus.Listen(0.02);
  }
  bus.Publish(ch::kStereoCommand, Encoded(bad_argument));
  ++bad_commands.sent;
  const int good_corners = int(corners.size());
  const bool collected = bus.ListenUntil(30, [&] {
    const auto c = bus.Counters(ch::kStereoCorners);
    const auto k = bus.Counters(ch::kStereoCommand);
    return c.received > 0 && c.received == good_corners + c.rejected && k.received > 0 && k.received == k.rejected;
  });
  bus.Publish(ch::kStereoCommand, AsSent(ch::kStereoCommand, CommandMessage("solve", "stereo-calibrate")));
  const bool solved = bus.ListenUntil(120, [&] { return !bus.Payloads(ch::kStereoCalibration).empty(); });
  const bool settled = bus.ListenUntil(10, [&] {  // a PROCESS_STATUS that counts the solve command
    const auto k = bus.Counters(ch::kStereoCommand);
    return k.received == 1 + k.rejected;
  });
  process.Signal(SIGINT);
  const auto r = process.Wait(30);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(collected) << "the counters never accounted for everything sent";
  ASSERT_TRUE(solved) << r.output;
  EXPECT_TRUE(settled) << "no status counted the solve command";
  EXPECT_EQ(ReadFileText(live_file), ReadFileText(clean_file));
  ExpectRejectedAllBad(bus, bad_corners, good_corners);
  ExpectRejectedAllBad(bus, bad_commands, 1);
}

TEST_P(BadPeer, StereoCloudRejectsItAllAndFiltersTheSame) {
  const std::string dir = TempDir("faults-cloud");
  std::vector<ws::PointCloud> clouds;
  std::vector<LogEvent> clean_in;
  for (int i = 0; i < 3; ++i) {
    // The wall moved by i cm, so that every frame's output differs.
    ws::PointCloud cloud = ws::testing::NoisyWallScene();
    for (auto& p : cloud.xyz) p[2] += 0.01f * float(i);
    cloud.frame_id = i;
    cloud.utime = (i + 1) * 200000;
    clouds.push_back(cloud);
    clean_in.push_back(Event(ch::kStereoCloud, cloud));
  }
  const auto clean = CleanRun(dir, clean_in, {"stereo-cloud"}, ch::kStereoCloudFiltered);
  ASSERT_EQ(clean.size(), clouds.size());

  const std::string url = UniqueUdpmUrl(15) + "&recv_buf_size=8388608";
  std::vector<std::string> argv = {"stereo-cloud", "--log-dir", dir, "--in-url", url, "--out-url", url};
  for (const std::string& arg : KeyArgs(dir)) argv.push_back(arg);
  Command process(argv);
  BusWatch bus(url, "stereo-cloud");
  bus.Collect(ch::kStereoCloudFiltered);
  ASSERT_TRUE(bus.ListenUntil(20, [&] { return bus.status().has_value(); })) << process.Output();

  auto bad_intensity = clouds[0];
  bad_intensity.nintensity = 1;
  bad_intensity.intensity = {1.0f};
  BadChannel bad_clouds{ch::kStereoCloud, BadMessages(Encoded(clouds[0]), Encoded(CommandMessage("save", "")),
                                                      Encoded(bad_intensity), 12)};
  BadChannel bad_commands{ch::kStereoCommand, BadMessages(Encoded(CommandMessage("save", "stereo-cloud")),
                                                          Encoded(clouds[0]),
                                                          Encoded(CommandMessage("frobnicate", "stereo-cloud")), 13)};
  const std::vector<BadChannel*> both = {&bad_clouds, &bad_commands};
  for (const auto& cloud : clouds) {
    Flood(bus, both);
    bus.Publish(ch::kStereoCloud, cloud);
    const size_t expected = size_t(cloud.frame_id + 1);
    bus.ListenUntil(30, [&] { return bus.Payloads(ch::kStereoCloudFiltered).size() >= expected; });
  }
  const int good = int(clouds.size());
  const bool settled = bus.ListenUntil(30, [&] {
    const auto c = bus.Counters(ch::kStereoCloud);
    const auto k = bus.Counters(ch::kStereoCommand);
    return c.received > 0 && c.received == good + c.rejected && k.received == k.rejected &&
           bus.Counters(ch::kStereoCloudFiltered).published == good;
  });
  process.Signal(SIGINT);
  const auto r = process.Wait(30);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(settled) << "the counters never accounted for everything sent";
  EXPECT_EQ(bus.Payloads(ch::kStereoCloudFiltered), clean);
  ExpectRejectedAllBad(bus, bad_clouds, good);
  ExpectRejectedAllBad(bus, bad_commands, 0);
}

}  // namespace
