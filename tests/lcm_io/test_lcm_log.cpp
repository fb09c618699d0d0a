#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "lcm_io/lcm_log.h"
#include "test_support.h"
#include "widestereo/command_t.hpp"

namespace {

widestereo::command_t Command(const std::string& what) {
  widestereo::command_t c{};
  c.command = what;
  c.nargs = 0;
  return c;
}

TEST(LcmLog, ScanCountsCompleteEventsAndFindsTheCut) {
  const std::string path = ws::test::TempDir("scan") + "/x.lcmlog";
  ws::test::WriteLog(path, {ws::test::Event("A", Command("solve")),
                            ws::test::Event("B", Command("reset"))});
  const ws::LcmLogScan whole = ws::ScanLcmLog(path);
  EXPECT_TRUE(whole.complete()) << whole.problem;
  EXPECT_EQ(whole.events, 2);
  EXPECT_EQ(whole.valid_bytes, whole.file_bytes);

  std::filesystem::resize_file(path, whole.file_bytes - 3);
  const ws::LcmLogScan cut = ws::ScanLcmLog(path);
  EXPECT_FALSE(cut.complete());
  EXPECT_EQ(cut.events, 1);
  EXPECT_NE(cut.problem.find("cut off"), std::string::npos) << cut.problem;
}

// A log of `before` events, `damage`, then one more event.
std::string DamagedLog(const std::string& name, int before, const std::string& damage) {
  const std::string dir = ws::test::TempDir(name);
  std::vector<ws::test::LogEvent> events;
  for (int i = 0; i < before; ++i) events.push_back(ws::test::Event("A", Command("solve")));
  ws::test::WriteLog(dir + "/head.lcmlog", events);
  ws::test::WriteLog(dir + "/tail.lcmlog", {ws::test::Event("B", Command("reset"))});
  std::ofstream out(dir + "/x.lcmlog", std::ios::binary);
  out << std::ifstream(dir + "/head.lcmlog", std::ios::binary).rdbuf() << damage
      << std::ifstream(dir + "/tail.lcmlog", std::ios::binary).rdbuf();
  return dir + "/x.lcmlog";
}

// LCM 1.3.1 takes an event only when a sync word follows it: garbage after
// the complete events would cost the last of them.
TEST(LcmLog, ScanSaysWhereLcmWouldNotReplayExactlyTheCompleteEvents) {
  const ws::LcmLogScan garbage = ws::ScanLcmLog(DamagedLog("garbage", 2, "\x01\x02\x03\x04\x05"));
  EXPECT_EQ(garbage.events, 2);
  EXPECT_NE(garbage.problem.find("bad sync word"), std::string::npos) << garbage.problem;
  EXPECT_FALSE(garbage.lcm_replays_exactly);

  // A cut at the end of the file: LCM stops right there.
  const std::string path = ws::test::TempDir("tail-cut") + "/x.lcmlog";
  ws::test::WriteLog(path, {ws::test::Event("A", Command("solve")), ws::test::Event("B", Command("reset"))});
  std::filesystem::resize_file(path, std::filesystem::file_size(path) - 3);
  const ws::LcmLogScan cut = ws::ScanLcmLog(path);
  EXPECT_EQ(cut.events, 1);
  EXPECT_TRUE(cut.lcm_replays_exactly);
  // Fewer than 4 bytes after the last event: not even a sync word to check.
  std::filesystem::resize_file(path, cut.valid_bytes + 3);
  const ws::LcmLogScan stub = ws::ScanLcmLog(path);
  EXPECT_EQ(stub.events, 1);
  EXPECT_NE(stub.problem.find("truncated event header"), std::string::npos) << stub.problem;
  EXPECT_TRUE(stub.lcm_replays_exactly);
}

TEST(LcmLog, CopyOfTheCompleteEventsIsACompleteLog) {
  const std::string path = DamagedLog("copy", 2, "garbage");
  const ws::LcmLogScan scan = ws::ScanLcmLog(path);
  const std::string copy = path + ".copy";
  ws::CopyCompleteEvents(path, scan, copy);
  const ws::LcmLogScan copied = ws::ScanLcmLog(copy);
  EXPECT_TRUE(copied.complete()) << copied.problem;
  EXPECT_EQ(copied.events, 2);
  EXPECT_EQ(ws::test::ReadLog(copy).size(), 2u);
}

TEST(LcmLog, FileUrlPath) {
  EXPECT_EQ(ws::LcmFileUrlPath("file:///tmp/a.lcmlog?speed=0"), "/tmp/a.lcmlog");
  EXPECT_EQ(ws::LcmFileUrlPath("udpm://239.255.76.67:7667"), "");
  EXPECT_EQ(ws::LcmFileUrlWithPath("file:///tmp/a.lcmlog?speed=0", "/b/c.lcmlog"),
            "file:///b/c.lcmlog?speed=0");
  EXPECT_EQ(ws::LcmFileUrlWithPath("file:///tmp/a.lcmlog", "/b.lcmlog"), "file:///b.lcmlog");
}

}  // namespace
