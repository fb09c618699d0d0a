#include <gtest/gtest.h>

#include <filesystem>

#include "lcm_io/lcm_log.h"
#include "test_support.h"
#include "widestereo/command_t.hpp"

namespace {

widestereo::command_t Command(const std::string& what) {
  widestereo::command_t c;
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

TEST(LcmLog, FileUrlPath) {
  EXPECT_EQ(ws::LcmFileUrlPath("file:///tmp/a.lcmlog?speed=0"), "/tmp/a.lcmlog");
  EXPECT_EQ(ws::LcmFileUrlPath("udpm://239.255.76.67:7667"), "");
}

}  // namespace
