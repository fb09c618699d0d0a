// StatusBoard's rules: what stereo-status shows stays true.
#include <gtest/gtest.h>

#include <sstream>

#include "monitor/status_board.h"

namespace {

widestereo::process_status_t Status(const std::string& name, int pid, const std::string& state = "running") {
  widestereo::process_status_t s{};
  s.utime = 1000000;
  s.name = name;
  s.host = "a-robot-with-a-long-host-name";
  s.pid = pid;
  s.uptime_s = 42;
  s.state = state;
  widestereo::channel_counters_t images{};
  images.channel = "STEREO_IMAGES";
  images.received = 100;
  images.dropped = 3;
  images.skipped = 40;
  s.channels = {images};
  s.nchannels = 1;
  return s;
}

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::string LineWith(const std::string& text, const std::string& what) {
  for (const auto& line : Lines(text))
    if (line.find(what) != std::string::npos) return line;
  return "";
}

TEST(StatusBoard, FullNamesAndLossesApartFromSkips) {
  ws::StatusBoard board;
  board.Add(Status("stereo-calibrate", 7), 0);
  const std::string table = board.Render(1000000);
  EXPECT_NE(table.find("stereo-calibrate@a-robot-with-a-long-host-name"), std::string::npos) << table;
  EXPECT_NE(table.find("LOST"), std::string::npos);
  EXPECT_NE(table.find("SKIPPED"), std::string::npos);
  // The channel row: 100 in, 3 lost, 40 skipped.
  const std::string row = LineWith(table, "STEREO_IMAGES");
  std::istringstream fields(row);
  std::vector<std::string> words;
  for (std::string word; fields >> word;) words.push_back(word);
  ASSERT_EQ(words.size(), 7u) << row;  // channel in out rate lost skipped rejected
  EXPECT_EQ(words[4], "3") << row;
  EXPECT_EQ(words[5], "40") << row;
}

TEST(StatusBoard, EachStagesTimePerFrameUnderItsProcess) {
  ws::StatusBoard board;
  auto status = Status("stereo-match", 7);
  for (const char* name : {"receive STEREO_IMAGES", "rectify", "match", "cloud", "publish STEREO_CLOUD"}) {
    widestereo::stage_time_t t{};
    t.stage = name;
    t.count = t.window = 100;
    t.median_ms = 12.3f;
    t.p99_ms = 40.5f;
    status.stages.push_back(t);
  }
  status.nstages = int32_t(status.stages.size());
  board.Add(status, 0);
  const std::string table = board.Render(1000000, {60, 0});
  const std::string line = LineWith(table, "ms median/p99:");
  EXPECT_NE(line.find("receive STEREO_IMAGES 12.3/40.5,"), std::string::npos) << table;
  for (const char* entry : {"rectify 12.3/40.5,", "match 12.3/40.5,", "publish STEREO_CLOUD 12.3/40.5\n"})
    EXPECT_NE(table.find(entry), std::string::npos) << entry << " in\n" << table;
  for (const auto& l : Lines(table)) EXPECT_LE(l.size(), 60u) << l;  // broken between stages, not cut
  // Gone: no budget, it is not current.
  EXPECT_EQ(board.Render(10000000).find("ms median/p99"), std::string::npos);
}

TEST(StatusBoard, SilentProcessesAreGoneAndEndedOnesSaySo) {
  ws::StatusBoard board;
  board.Add(Status("stereo-detect", 1), 0);
  board.Add(Status("stereo-match", 2, "exited"), 0);
  board.Add(Status("stereo-cloud", 3), 9000000);
  board.Add(Status("stereo-capture", 4, "stopped"), 0);  // by a signal: not "gone", not "exited"
  const std::string table = board.Render(10000000);
  EXPECT_NE(LineWith(table, "stereo-capture@").find("stopped"), std::string::npos) << table;
  EXPECT_NE(LineWith(table, "stereo-detect@").find("gone"), std::string::npos) << table;
  EXPECT_NE(LineWith(table, "stereo-match@").find("exited"), std::string::npos) << table;
  EXPECT_NE(LineWith(table, "stereo-cloud@").find("running"), std::string::npos) << table;
  EXPECT_EQ(board.Render(1000000).find("gone"), std::string::npos);
}

TEST(StatusBoard, FitsTheScreenAndWrapsTheHintBetweenWords) {
  ws::StatusBoard board;
  for (int pid = 1; pid <= 30; ++pid) board.Add(Status("stereo-detect", pid), 0);
  widestereo::calibration_status_t calibration{};
  calibration.state = "collecting";
  calibration.rms = calibration.heldout_rms = -1;
  calibration.hint = "show the board in the top left and the bottom right corners of both images, tilted";
  board.Add(calibration);
  const ws::Screen screen{60, 45};
  const std::string table = board.Render(1000000, screen);
  const auto lines = Lines(table);
  EXPECT_LE(lines.size(), size_t(screen.rows - 1)) << table;
  for (const auto& line : lines) EXPECT_LE(line.size(), size_t(screen.cols)) << line;
  EXPECT_EQ(table.find("STEREO_IMAGES"), std::string::npos) << "condensed to a line per process: " << table;
  EXPECT_NE(table.find("hint: show the board"), std::string::npos) << table;
  for (const auto& line : lines)  // no word cut at the end of a hint line
    if (line.rfind("hint: ", 0) == 0 || line.rfind("      ", 0) == 0) {
      EXPECT_NE(line.back(), ' ') << line;
    }
  EXPECT_NE(table.find("tilted"), std::string::npos) << table;
  // A screen too small even for one line a process: cut, and says so.
  EXPECT_NE(board.Render(1000000, {60, 12}).find("more lines: a taller terminal shows them"), std::string::npos);
}

TEST(StatusBoard, DepthLineFromCloudStats) {
  ws::StatusBoard board;
  widestereo::cloud_stats_t stats{};
  stats.frame_id = 9;
  stats.plane_found = true;
  stats.plane_offset = -2.0;
  stats.inlier_rms = 0.0012;
  stats.stage_names = {"input", "plane"};
  stats.stage_points = {76800, 25000};
  stats.stage_ms = {1, 2};
  stats.nstages = 2;
  board.Add(stats, 0);
  board.Add(stats, 500000);
  const std::string line = LineWith(board.Render(600000), "depth:");
  EXPECT_NE(line.find("25000 points"), std::string::npos) << line;
  EXPECT_NE(line.find("plane 2.000 m away (inlier RMS 1.2 mm)"), std::string::npos) << line;
  EXPECT_NE(line.find("2.0 clouds/s"), std::string::npos) << line;
  EXPECT_NE(LineWith(board.Render(9000000), "depth:").find("no cloud for"), std::string::npos);
}

}  // namespace
