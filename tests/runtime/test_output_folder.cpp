// FileInFolder: the one rule for every command argument that names a file.
#include <gtest/gtest.h>

#include <stdexcept>

#include "runtime/output_folder.h"

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

}  // namespace
