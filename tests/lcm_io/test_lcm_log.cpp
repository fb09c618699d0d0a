#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "lcm_io/decode.h"
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

// The check of a log of commands: the data decodes as a command_t.
bool IsCommand(const std::string&, const uint8_t* data, size_t size) {
  try {
    ws::DecodeMessage<widestereo::command_t>(data, int(size));
    return true;
  } catch (const ws::DecodeError&) {
    return false;
  }
}

// `n` commands "c0", "c1", ... in a log at `path`; returns where each event starts.
std::vector<int64_t> CommandLog(const std::string& path, int n) {
  std::vector<ws::test::LogEvent> events;
  std::vector<int64_t> starts;
  int64_t at = 0;
  for (int i = 0; i < n; ++i) {
    events.push_back(ws::test::Event("CMD", Command("c" + std::to_string(i))));
    starts.push_back(at);
    at += 4 + 8 + 8 + 4 + 4 + 3 + int64_t(events.back().data.size());
  }
  ws::test::WriteLog(path, events);
  return starts;
}

std::vector<std::string> Commands(const ws::LcmLogRecovery& recovery) {
  std::vector<std::string> out;
  for (const auto& event : recovery.events)
    out.push_back(ws::DecodeMessage<widestereo::command_t>(event.data.data(), int(event.data.size())).command);
  return out;
}

void FlipByte(const std::string& path, int64_t at) {
  std::fstream file(path, std::ios::in | std::ios::out | std::ios::binary);
  file.seekg(at);
  const char byte = char(file.get());
  file.seekp(at);
  file.put(char(byte ^ 0x5A));
}

TEST(LcmLog, RecoveryOfAnIntactLogIsTheLogItself) {
  const std::string path = ws::test::TempDir("recover-intact") + "/x.lcmlog";
  CommandLog(path, 4);
  const ws::LcmLogRecovery recovery = ws::RecoverLcmLog(path, IsCommand);
  EXPECT_TRUE(recovery.intact()) << recovery.first_damage;
  EXPECT_EQ(recovery.lost_events, 0);
  EXPECT_EQ(Commands(recovery), (std::vector<std::string>{"c0", "c1", "c2", "c3"}));
  EXPECT_EQ(ws::EncodeLcmLog(recovery.events), ws::test::ReadFileText(path));
}

// One flipped byte in the sync word, the channel length or the data length
// of the 6th event costs that event only.
TEST(LcmLog, RecoveryResynchronisesPastAFlippedHeaderByte) {
  for (const int byte : {0, 3, 23, 27}) {
    SCOPED_TRACE("header byte " + std::to_string(byte));
    const std::string path = ws::test::TempDir("recover-flip") + "/x.lcmlog";
    const std::vector<int64_t> starts = CommandLog(path, 10);
    FlipByte(path, starts[5] + byte);
    const ws::LcmLogRecovery recovery = ws::RecoverLcmLog(path, IsCommand);
    EXPECT_EQ(Commands(recovery), (std::vector<std::string>{"c0", "c1", "c2", "c3", "c4", "c6", "c7", "c8", "c9"}));
    EXPECT_EQ(recovery.lost_events, 1);
    EXPECT_EQ(recovery.lost_bytes, starts[6] - starts[5]);
    EXPECT_EQ(recovery.file_bytes, int64_t(std::filesystem::file_size(path)));
    EXPECT_NE(recovery.first_damage.find("at byte " + std::to_string(starts[5])), std::string::npos)
        << recovery.first_damage;
    // What is recovered is an intact log.
    std::ofstream(path + ".recovered", std::ios::binary) << ws::EncodeLcmLog(recovery.events);
    EXPECT_TRUE(ws::ScanLcmLog(path + ".recovered").complete());
    EXPECT_EQ(ws::test::ReadLog(path + ".recovered").size(), 9u);
  }
}

// Garbage between events loses no event, even garbage holding a sync word
// and a plausible header whose data is not a command.
TEST(LcmLog, RecoverySkipsGarbageBetweenEvents) {
  const std::string path = ws::test::TempDir("recover-garbage") + "/x.lcmlog";
  const std::vector<int64_t> starts = CommandLog(path, 4);
  std::string log = ws::test::ReadFileText(path);
  const std::string fake_event = std::string("\xED\xA1\xDA\x01", 4) + std::string(16, '\0') +
                                 std::string("\0\0\0\x03\0\0\0\x05", 8) + "CMDjunk!";
  const std::string garbage = "\x01\x02\x03" + fake_event + "\x04";
  log.insert(size_t(starts[2]), garbage);
  std::ofstream(path, std::ios::binary) << log;
  const ws::LcmLogRecovery recovery = ws::RecoverLcmLog(path, IsCommand);
  EXPECT_EQ(Commands(recovery), (std::vector<std::string>{"c0", "c1", "c2", "c3"}));
  EXPECT_EQ(recovery.lost_bytes, int64_t(garbage.size()));
  EXPECT_EQ(recovery.lost_events, 0);  // the numbers 1 and 2 on either side
  EXPECT_NE(recovery.first_damage.find("bad sync word at byte " + std::to_string(starts[2])), std::string::npos)
      << recovery.first_damage;
}

// A log cut in its last event (a kill during a write) keeps every event before.
TEST(LcmLog, RecoveryOfATruncatedTailKeepsTheEventsBefore) {
  const std::string path = ws::test::TempDir("recover-cut") + "/x.lcmlog";
  const std::vector<int64_t> starts = CommandLog(path, 5);
  const int64_t size = int64_t(std::filesystem::file_size(path));
  std::filesystem::resize_file(path, size - 3);
  const ws::LcmLogRecovery recovery = ws::RecoverLcmLog(path, IsCommand);
  EXPECT_EQ(Commands(recovery), (std::vector<std::string>{"c0", "c1", "c2", "c3"}));
  EXPECT_EQ(recovery.lost_bytes, size - 3 - starts[4]);
  EXPECT_EQ(recovery.lost_events, 1);
  EXPECT_NE(recovery.first_damage.find("event cut off at byte " + std::to_string(starts[4])), std::string::npos)
      << recovery.first_damage;
  // Nothing recoverable at all: every byte lost, nothing thrown.
  std::filesystem::resize_file(path, 10);
  const ws::LcmLogRecovery nothing = ws::RecoverLcmLog(path, IsCommand);
  EXPECT_TRUE(nothing.events.empty());
  EXPECT_EQ(nothing.lost_bytes, 10);
  EXPECT_THROW(ws::RecoverLcmLog(path + ".absent", IsCommand), std::runtime_error);
}

TEST(LcmLog, FileUrlPath) {
  EXPECT_EQ(ws::LcmFileUrlPath("file:///tmp/a.lcmlog?speed=0"), "/tmp/a.lcmlog");
  EXPECT_EQ(ws::LcmFileUrlPath("udpm://239.255.76.67:7667"), "");
  EXPECT_EQ(ws::LcmFileUrlWithPath("file:///tmp/a.lcmlog?speed=0", "/b/c.lcmlog"),
            "file:///b/c.lcmlog?speed=0");
  EXPECT_EQ(ws::LcmFileUrlWithPath("file:///tmp/a.lcmlog", "/b.lcmlog"), "file:///b.lcmlog");
}

}  // namespace
