// CommandOutputFile: the one rule for every command argument that names a
// file; KeepBackup: what an overwrite keeps; RequireWritableFolderOf: an
// output option checked before any work.
#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "runtime/atomic_file.h"
#include "runtime/output_folder.h"
#include "test_support.h"

namespace {

std::string What(const ws::CommandOutput& output) {
  try {
    ws::CommandOutputFile(output);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(CommandOutputFile, OnlyANewPlainFileOfTheCommandsKindInTheFolder) {
  EXPECT_EQ(ws::CommandOutputFile({"/data/clouds", "cloud.pcd", ".pcd"}), "/data/clouds/cloud.pcd");
  EXPECT_EQ(ws::CommandOutputFile({".", "calib2.yaml", ".yaml"}), "./calib2.yaml");
  for (const char* name : {"", "/tmp/outside.pcd", "../x.pcd", "..", "sub/x.pcd", "a/../../b.pcd", "x..pcd", "/",
                           "a\nb.pcd", "tab\t.pcd", ".pcd"})
    EXPECT_NE(What({"/data/clouds", name, ".pcd"}), "") << name;
  EXPECT_NE(What({"/data/clouds", std::string(300, 'a') + ".pcd", ".pcd"}), "");
  EXPECT_EQ(What({"/data/clouds", "../x.pcd", ".pcd"}),
            "not a plain file name (no '/', no '..', no control characters, at most 200 bytes); files go only "
            "into /data/clouds");
  // Another kind: the views state, a log, a recording, a report for a calibration.
  for (const char* name : {"stereo-calibrate-views.lcmlog", "stereo-calibrate.log", "run.lcmlog", "calib.json"})
    EXPECT_EQ(What({"/data", name, ".yaml"}), "this command writes only .yaml files") << name;
  EXPECT_NE(What({"", "cloud.pcd", ".pcd"}), "");
}

TEST(CommandOutputFile, AnExistingFileOrSymlinkOnlyWithOverwriteAndKeptAsABackup) {
  const std::string dir = ws::test::TempDir("command-output");
  ws::WriteFileAtomically(dir + "/refined.yaml", "old\n");
  std::filesystem::create_symlink("/nonexistent/target.yaml", dir + "/dangling.yaml");
  EXPECT_EQ(What({dir, "refined.yaml", ".yaml"}),
            dir + "/refined.yaml exists; overwrite=1 replaces it and keeps the old one as a backup");
  EXPECT_NE(What({dir, "dangling.yaml", ".yaml"}), "");
  EXPECT_EQ(ws::CommandOutputFile({dir, "refined.yaml", ".yaml", true}), dir + "/refined.yaml");

  EXPECT_EQ(ws::KeepBackup(dir + "/refined.yaml"), dir + "/refined.yaml.1.bak");
  EXPECT_EQ(ws::KeepBackup(dir + "/refined.yaml"), dir + "/refined.yaml.2.bak");  // never replaces a backup
  ws::WriteFileAtomically(dir + "/refined.yaml", "new\n");
  EXPECT_EQ(ws::test::ReadFileText(dir + "/refined.yaml"), "new\n");
  EXPECT_EQ(ws::test::ReadFileText(dir + "/refined.yaml.1.bak"), "old\n");
  EXPECT_EQ(ws::KeepBackup(dir + "/none.yaml"), "");
}

// A peer repeating `save ... overwrite=1` (400 of them once made 400
// backups) keeps only the last kKeptBackups, numbered on from the newest.
TEST(KeepBackup, KeepsOnlyTheLastBackups) {
  const std::string dir = ws::test::TempDir("backups");
  for (int i = 1; i <= 25; ++i) {
    ws::WriteFileAtomically(dir + "/calib.yaml", "version " + std::to_string(i) + "\n");
    ws::KeepBackup(dir + "/calib.yaml");
  }
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) names.push_back(entry.path().filename().string());
  EXPECT_EQ(long(names.size()), ws::kKeptBackups + 1) << ::testing::PrintToString(names);
  EXPECT_EQ(ws::test::ReadFileText(dir + "/calib.yaml.25.bak"), "version 25\n");
  EXPECT_EQ(ws::test::ReadFileText(dir + "/calib.yaml.16.bak"), "version 16\n");
  EXPECT_FALSE(std::filesystem::exists(dir + "/calib.yaml.15.bak"));
}

TEST(RequireWritableFolderOf, AMissingFolderIsAnErrorNamingTheOptionAndTheFolder) {
  const std::string dir = ws::test::TempDir("writable-folder");
  EXPECT_NO_THROW(ws::RequireWritableFolderOf("--out", dir + "/calib.yaml"));
  EXPECT_NO_THROW(ws::RequireWritableFolderOf("--out", "calib.yaml"));  // the working folder
  EXPECT_NO_THROW(ws::RequireWritableFolderOf("--report", ""));         // none asked for
  try {
    ws::RequireWritableFolderOf("--report", dir + "/missing/report.json");
    ADD_FAILURE() << "a missing folder passed";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "--report " + dir + "/missing/report.json: the folder " + dir +
                                         "/missing does not exist");
  }
}

TEST(RequireWritableFolderOf, StereoCalibrateRefusesAnOutFolderThatIsNotThereBeforeItStarts) {
  const std::string dir = ws::test::TempDir("calibrate-out-missing");
  const auto run = ws::test::RunCommand(
      {"stereo-calibrate", "--once", "--log-dir", dir, "--in-url", "file://" + dir + "/none.lcmlog?speed=0",
       "--out", dir + "/missing/calib.yaml"},
      30);
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_NE(run.output.find("--out " + dir + "/missing/calib.yaml: the folder " + dir +
                            "/missing does not exist"),
            std::string::npos)
      << run.output;
}

}  // namespace
