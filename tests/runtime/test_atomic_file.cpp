// WriteFileAtomically: the old file or the whole new one, never a part, a
// planted symlink never followed, no temporary left behind.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <stdexcept>

#include "runtime/atomic_file.h"
#include "test_support.h"

namespace {

namespace fs = std::filesystem;

// The names in `dir`, to see that no temporary was left.
std::vector<std::string> Names(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(WriteFileAtomically, ReplacesTheFileAndLeavesNoTemporary) {
  const std::string dir = ws::test::TempDir("atomic-write");
  ws::WriteFileAtomically(dir + "/calib.yaml", "first\n");
  ws::WriteFileAtomically(dir + "/calib.yaml", "second\n");
  EXPECT_EQ(ws::test::ReadFileText(dir + "/calib.yaml"), "second\n");
  EXPECT_EQ(Names(dir), std::vector<std::string>{"calib.yaml"});
}

TEST(WriteFileAtomically, APlantedSymlinkIsReplacedNotFollowed) {
  const std::string dir = ws::test::TempDir("atomic-symlink");
  const std::string outside = ws::test::TempDir("atomic-symlink-outside") + "/victim.yaml";
  ws::WriteFileAtomically(outside, "victim\n");
  fs::create_symlink(outside, dir + "/calib.yaml");
  ws::WriteFileAtomically(dir + "/calib.yaml", "calibration\n");
  EXPECT_EQ(ws::test::ReadFileText(outside), "victim\n");
  EXPECT_FALSE(fs::is_symlink(dir + "/calib.yaml"));
  EXPECT_EQ(ws::test::ReadFileText(dir + "/calib.yaml"), "calibration\n");
}

// A full disk, as the file size limit makes it (EFBIG where ENOSPC would
// be): the write fails, saying so, and the old file stays whole.
TEST(WriteFileAtomically, AFailedWriteLeavesTheOldFileAndNoTemporary) {
  const std::string dir = ws::test::TempDir("atomic-full");
  ws::WriteFileAtomically(dir + "/calib.yaml", "good calibration\n");
  rlimit before;
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &before), 0);
  const auto handler = std::signal(SIGXFSZ, SIG_IGN);
  rlimit small = before;
  small.rlim_cur = 4096;
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &small), 0);
  std::string error;
  try {
    ws::WriteFileAtomically(dir + "/calib.yaml", std::string(100000, 'x'));
  } catch (const std::runtime_error& e) {
    error = e.what();
  }
  setrlimit(RLIMIT_FSIZE, &before);
  std::signal(SIGXFSZ, handler);
  EXPECT_EQ(error.rfind("cannot write '" + dir + "/calib.yaml': writing: File too large", 0), 0u) << error;
  EXPECT_EQ(ws::test::ReadFileText(dir + "/calib.yaml"), "good calibration\n");
  EXPECT_EQ(Names(dir), std::vector<std::string>{"calib.yaml"});
}

// A set of files (a calibration, its model files, its report): a write that
// fails part-way through the set leaves every old file whole and no
// temporary; committed, all are in place.
TEST(OutputSet, AFailureAnywhereLeavesTheOldSetWhole) {
  const std::string dir = ws::test::TempDir("output-set");
  ws::WriteFileAtomically(dir + "/calib.yaml", "old calibration\n");
  ws::WriteFileAtomically(dir + "/calib.report.json", "old report\n");
  try {
    ws::OutputSet set;
    ws::WriteFileAtomically(dir + "/calib.yaml", "new calibration\n");  // into the set
    ws::WriteFileAtomically(dir + "/missing/calib.report.json", "new report\n");  // fails
    set.Commit();
    FAIL() << "the second file cannot be written";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("missing/calib.report.json"), std::string::npos) << e.what();
  }
  EXPECT_EQ(ws::test::ReadFileText(dir + "/calib.yaml"), "old calibration\n");
  EXPECT_EQ(Names(dir), (std::vector<std::string>{"calib.report.json", "calib.yaml"}));

  {
    ws::OutputSet set;
    ws::WriteFileAtomically(dir + "/calib.yaml", "new calibration\n");
    ws::WriteFileAtomically(dir + "/calib.report.json", "new report\n");
    EXPECT_EQ(ws::test::ReadFileText(dir + "/calib.yaml"), "old calibration\n") << "not before the commit";
    set.Commit();
  }
  EXPECT_EQ(ws::test::ReadFileText(dir + "/calib.yaml"), "new calibration\n");
  EXPECT_EQ(ws::test::ReadFileText(dir + "/calib.report.json"), "new report\n");
  EXPECT_EQ(Names(dir), (std::vector<std::string>{"calib.report.json", "calib.yaml"}));
}

TEST(WriteFileAtomically, AMissingFolderIsAnError) {
  EXPECT_THROW(ws::WriteFileAtomically("/nonexistent/folder/calib.yaml", "x"), std::runtime_error);
}

}  // namespace
