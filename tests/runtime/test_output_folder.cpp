// FileInFolder: the one rule for every command argument that names a file;
// RequireWritableFolderOf: an output option checked before any work.
#include <gtest/gtest.h>

#include <stdexcept>

#include "runtime/output_folder.h"
#include "test_support.h"

namespace {

TEST(FileInFolder, OnlyAPlainFileNameInTheFolder) {
  EXPECT_EQ(ws::FileInFolder("/data/clouds", "cloud.pcd"), "/data/clouds/cloud.pcd");
  EXPECT_EQ(ws::FileInFolder(".", "calib2.yaml"), "./calib2.yaml");
  for (const char* name : {"", "/tmp/outside.pcd", "../x.pcd", "..", "sub/x.pcd", "a/../../b", "x..pcd", "/"})
    EXPECT_THROW(ws::FileInFolder("/data/clouds", name), std::invalid_argument) << name;
  try {
    ws::FileInFolder("/data/clouds", "../x.pcd");
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "'../x.pcd' is not a plain file name (no '/', no '..'); files go only into /data/clouds");
  }
  EXPECT_THROW(ws::FileInFolder("", "cloud.pcd"), std::invalid_argument);
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
