// stereo-cloud as a real process over LCM, log to log: a wall cloud filtered
// with its plane reported, PCD files every N clouds and on `save`, bad clouds
// published empty and counted without stalling, commands checked, and bad
// settings refused with their reason.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <limits>
#include <map>
#include <set>

#include "cloud/pcd_io.h"
#include "cloud_test_support.h"
#include "lcm_io/channels.h"
#include "test_support.h"
#include "widestereo/cloud_stats_t.hpp"
#include "widestereo/process_status_t.hpp"

namespace {

using namespace ws::test;
using ws::testing::MakeCloud;
using ws::testing::Point;

ws::PointCloud Framed(ws::PointCloud cloud, int64_t frame_id) {
  cloud.frame_id = frame_id;
  cloud.utime = 1000000 * frame_id;
  return cloud;
}

// stereo-cloud from the log `dir`/in.lcmlog to `dir`/out.lcmlog.
CommandResult RunStereoCloud(const std::string& dir, const std::vector<LogEvent>& input,
                             std::vector<std::string> extra = {}) {
  WriteLog(dir + "/in.lcmlog", input);
  std::vector<std::string> argv = {"stereo-cloud", "--log-dir", dir, "--in-url",
                                   "file://" + dir + "/in.lcmlog?speed=0", "--out-url",
                                   "file://" + dir + "/out.lcmlog?mode=w"};
  argv.insert(argv.end(), extra.begin(), extra.end());
  return RunCommand(argv, 60);
}

TEST(StereoCloudProcess, FiltersTheWallAndWritesPcdFilesEveryNAndOnSave) {
  const std::string dir = TempDir("cloud-wall");
  const std::string saved = dir + "/pcd/asked.pcd";
  const auto wall = ws::testing::NoisyWallScene();
  const auto r = RunStereoCloud(
      dir,
      {Event(ws::channel::kStereoCloud, Framed(wall, 1)),
       Event(ws::channel::kStereoCommand, CommandMessage("save", "", {"path=asked.pcd"}, 1500000)),
       Event(ws::channel::kStereoCloud, Framed(wall, 2)),
       Event(ws::channel::kStereoCloud, Framed(wall, 3)),
       Event(ws::channel::kStereoCloud, Framed(wall, 4))},
      {"--pcd-dir", dir + "/pcd", "--save-every", "2"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // PCL's console stays quiet (RANSAC and the PCD writer print nothing).
  EXPECT_EQ(r.output.find("[pcl::"), std::string::npos) << r.output;

  const auto events = ReadLog(dir + "/out.lcmlog");
  const auto clouds = Messages<ws::PointCloud>(events, ws::channel::kStereoCloudFiltered);
  const auto stats = Messages<widestereo::cloud_stats_t>(events, ws::channel::kCloudStats);
  ASSERT_EQ(clouds.size(), 4u);
  ASSERT_EQ(stats.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(clouds[i].frame_id, i + 1);
    EXPECT_EQ(stats[i].frame_id, i + 1);
    EXPECT_EQ(clouds[i].frame, "left_rectified");
    ASSERT_TRUE(stats[i].plane_found);
    EXPECT_NEAR(stats[i].plane_offset, ws::testing::kWallZ, 1e-3);
    EXPECT_NEAR(stats[i].inlier_rms, ws::testing::kNoiseSigma, 0.05 * ws::testing::kNoiseSigma);
    EXPECT_EQ(stats[i].stage_points[0], wall.npoints);
    EXPECT_EQ(clouds[i].npoints, stats[i].stage_points[3]);  // the cloud after outlier removal
    EXPECT_LT(clouds[i].npoints, wall.npoints);
  }
  // Its budget: the filter, each of the chain's stages as a part of it and
  // the process's CPU time over it, timed on every cloud.
  const auto status = Messages<widestereo::process_status_t>(events, ws::channel::kProcessStatus);
  ASSERT_FALSE(status.empty());
  std::map<std::string, int64_t> timed;
  for (const auto& stage : status.back().stages) timed[stage.stage] = stage.count;
  for (const std::string stage : {"filter", "filter: input", "filter: passthrough", "filter: voxel",
                                  "filter: outliers", "filter: plane", "filter: CPU"})
    EXPECT_EQ(timed[stage], 4) << stage;

  // The save command wrote cloud 1; --save-every 2 wrote clouds 2 and 4.
  const auto asked = ws::ReadPcd(saved);
  EXPECT_EQ(asked.npoints, clouds[0].npoints);
  EXPECT_EQ(asked.xyz, clouds[0].xyz);
  EXPECT_EQ(asked.intensity, clouds[0].intensity);
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir + "/pcd"))
    files.push_back(entry.path().filename().string());
  std::sort(files.begin(), files.end());
  EXPECT_EQ(files, (std::vector<std::string>{"asked.pcd", "cloud_000002.pcd", "cloud_000004.pcd"}));
  EXPECT_EQ(ws::ReadPcd(dir + "/pcd/cloud_000004.pcd").npoints, clouds[3].npoints);

  // A line per cloud in the log file, with its plane.
  std::ifstream log(dir + "/stereo-cloud.log");
  const std::string text((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
  char line[64];
  std::snprintf(line, sizeof line, "frame 4: %d points in, %d out; plane 2.0", wall.npoints, clouds[3].npoints);
  EXPECT_NE(text.find(line), std::string::npos) << text;

  const auto in = LastCounters(dir + "/out.lcmlog", "stereo-cloud", ws::channel::kStereoCloud);
  EXPECT_EQ(in.received, 4);
  EXPECT_EQ(in.dropped, 0);
  EXPECT_EQ(in.rejected, 0);
}

// Empty, all-NaN and one-point clouds come out as empty clouds (with their
// stats) and are counted as dropped; a message that does not decode is
// rejected; the wall after them is filtered as usual (a stall would end in
// RunStereoCloud's time limit; the speed is bench/'s to measure).
TEST(StereoCloudProcess, BadCloudsGiveEmptyResultsCountedWithoutStalling) {
  const std::string dir = TempDir("cloud-bad");
  const float nan = std::numeric_limits<float>::quiet_NaN();
  LogEvent garbage{ws::channel::kStereoCloud, {1, 2, 3, 4, 5, 6, 7}, 0};
  const auto r = RunStereoCloud(
      dir, {Event(ws::channel::kStereoCloud, Framed(MakeCloud({}), 1)),
            Event(ws::channel::kStereoCloud,
                  Framed(MakeCloud(std::vector<Point>(5000, Point{nan, nan, nan})), 2)),
            Event(ws::channel::kStereoCloud,
                  Framed(MakeCloud(std::vector<Point>(200000, Point{0.5f, -0.25f, 2})), 3)),
            garbage,
            Event(ws::channel::kStereoCloud, Framed(ws::testing::NoisyWallScene(), 4))});
  ASSERT_EQ(r.exit_code, 0) << r.output;

  const auto events = ReadLog(dir + "/out.lcmlog");
  const auto clouds = Messages<ws::PointCloud>(events, ws::channel::kStereoCloudFiltered);
  const auto stats = Messages<widestereo::cloud_stats_t>(events, ws::channel::kCloudStats);
  ASSERT_EQ(clouds.size(), 4u);
  ASSERT_EQ(stats.size(), 4u);
  const int inputs[3] = {0, 5000, 200000};
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(clouds[i].npoints, 0) << i;
    EXPECT_FALSE(stats[i].plane_found) << i;
    EXPECT_EQ(stats[i].stage_points[0], inputs[i]) << i;
    EXPECT_EQ(stats[i].stage_points[1], 0) << i;  // nothing passed the pass-through
  }
  EXPECT_TRUE(stats[3].plane_found);
  EXPECT_GT(clouds[3].npoints, 0);

  // One error for the run of empty clouds, naming the first and why.
  EXPECT_NE(r.output.find("frame 1: no usable points in 0"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("frame 2: no usable points"), std::string::npos) << r.output;
  const auto c = LastCounters(dir + "/out.lcmlog", "stereo-cloud", ws::channel::kStereoCloud);
  EXPECT_EQ(c.received, 5);
  EXPECT_EQ(c.dropped, 3);
  EXPECT_EQ(c.rejected, 1);
  // The one-point cloud is explained in the log file.
  std::ifstream log(dir + "/stereo-cloud.log");
  const std::string text((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("frame 3: passthrough: all 200000 points are the one point (0.5, -0.25, 2)"),
            std::string::npos);
}

// `save` before any cloud, to a path outside --pcd-dir or without one, or an
// unknown command for stereo-cloud are rejected and counted; commands for
// others are ignored.
TEST(StereoCloudProcess, CommandsAreCheckedAndCounted) {
  const std::string dir = TempDir("cloud-commands");
  // A second apart, so that a PROCESS_STATUS with its last_error follows each.
  const auto cloud = Framed(MakeCloud({{0, 0, 1}, {1, 0, 1}, {0, 1, 1}}), 2);
  const std::vector<LogEvent> input = {
      Event(ws::channel::kStereoCommand, CommandMessage("save", "", {}, 1000000)),  // no cloud yet
      Event(ws::channel::kStereoCloud, cloud),
      Event(ws::channel::kStereoCommand, CommandMessage("save", "", {"path=../no.pcd"}, 3000000)),
      Event(ws::channel::kStereoCommand, CommandMessage("flush", "stereo-cloud", {}, 4000000)),
      Event(ws::channel::kStereoCommand, CommandMessage("solve", "", {}, 5000000)),
      Event(ws::channel::kStereoCommand, CommandMessage("save", "stereo-calibrate", {"path=no.pcd"}, 6000000)),
      Event(ws::channel::kStereoCommand, CommandMessage("save", "stereo-cloud", {"path=yes.pcd"}, 7000000))};
  auto errors = [&] {
    std::set<std::string> errors;
    for (const auto& status : Messages<widestereo::process_status_t>(ReadLog(dir + "/out.lcmlog"),
                                                                    ws::channel::kProcessStatus))
      errors.insert(status.last_error);
    return errors;
  };
  auto r = RunStereoCloud(dir, input, {"--pcd-dir", dir + "/pcd", "--save-every", "0"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(errors(), (std::set<std::string>{
                          "STEREO_COMMAND: save: no cloud has been filtered yet",
                          "STEREO_COMMAND: save: path='../no.pcd': not a plain file name (no '/', no '..', "
                          "no control characters, at most 200 bytes); files go only into " + dir + "/pcd",
                          "STEREO_COMMAND: unknown command 'flush' (stereo-cloud knows: save "
                          "[path=NAME.pcd])"}));
  EXPECT_FALSE(std::filesystem::exists(dir + "/no.pcd"));
  EXPECT_FALSE(std::filesystem::exists(dir + "/pcd/no.pcd"));
  EXPECT_EQ(ws::ReadPcd(dir + "/pcd/yes.pcd").npoints, 3);
  auto c = LastCounters(dir + "/out.lcmlog", "stereo-cloud", ws::channel::kStereoCommand);
  EXPECT_EQ(c.received, 6);
  EXPECT_EQ(c.rejected, 3);

  // Without --pcd-dir a save has nowhere to write.
  r = RunStereoCloud(dir, {input[1], input.back()});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(errors(), (std::set<std::string>{"", "STEREO_COMMAND: save: stereo-cloud was started without --pcd-dir"}));
  c = LastCounters(dir + "/out.lcmlog", "stereo-cloud", ws::channel::kStereoCommand);
  EXPECT_EQ(c.rejected, 1);
}

// Frame ids are wrap-safe counters: a gap of two is two frames stereo-match
// made no cloud of (it matches the newest pair), skipped by design and not
// lost; a jump to 2^62 or to INT64_MIN is the sender's reset, reported and
// not counted as 10^18 skips; INT64_MAX then INT64_MIN is the next frame.
TEST(StereoCloudProcess, FrameIdGapsAreSkipsAndJumpsAreResets) {
  const std::string dir = TempDir("cloud-frame-ids");
  std::vector<LogEvent> input;
  int64_t utime = 1000000;
  for (const int64_t id : {int64_t(1), int64_t(2), int64_t(5), int64_t(1) << 62, INT64_MIN, INT64_MAX, INT64_MIN}) {
    auto cloud = MakeCloud({{0, 0, 1}, {1, 0, 1}, {0, 1, 1}});
    cloud.frame_id = id;
    cloud.utime = utime += 1000000;
    input.push_back(Event(ws::channel::kStereoCloud, cloud));
  }
  const auto r = RunStereoCloud(dir, input);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto c = LastCounters(dir + "/out.lcmlog", "stereo-cloud", ws::channel::kStereoCloud);
  EXPECT_EQ(c.received, 7);
  EXPECT_EQ(c.skipped, 2) << "frames 3 and 4, passed over by stereo-match";
  EXPECT_EQ(c.dropped, 0) << "counted as lost";
  EXPECT_NE(r.output.find("STEREO_CLOUD: frame id jumped from 5 to 4611686018427387904: counted as the sender's "
                          "reset, not as lost frames"),
            std::string::npos)
      << r.output;
}

TEST(StereoCloudProcess, BadSettingsAreRefusedWithTheirReason) {
  const std::string dir = TempDir("cloud-settings");
  auto run = [&](std::vector<std::string> argv) {
    argv.insert(argv.begin(), {"stereo-cloud", "--log-dir", dir});
    return RunCommand(argv, 30);
  };
  auto r = run({"--z-min", "2", "--z-max", "1"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("--z-max: must be greater than --z-min (2), got 1"), std::string::npos)
      << r.output;
  r = run({"--save-every", "3"});
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("--save-every requires --pcd-dir"), std::string::npos) << r.output;
  std::ofstream(dir + "/bad.yaml") << "voxel-leaf: -1\n";
  r = run({"--config", dir + "/bad.yaml"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find(dir + "/bad.yaml: --voxel-leaf: must be > 0, got -1"), std::string::npos)
      << r.output;
  std::ofstream(dir + "/unknown.yaml") << "voxel-size: 0.01\n";
  r = run({"--config", dir + "/unknown.yaml"});
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("voxel-size"), std::string::npos) << r.output;
  r = run({"--help"});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.output.find("--plane-distance"), std::string::npos);
}

}  // namespace
