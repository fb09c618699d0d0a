// ReadBoundedFile: what is not a regular file of at most the size given is
// refused from its stat, before a byte is read (a FIFO would block, a
// device never end); LoadAnyRig and every reader behind it use it.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>

#include "interop/any_rig.h"
#include "rig/rig_file.h"
#include "runtime/bounded_file.h"
#include "test_support.h"

namespace {

std::string RefusalOf(const std::string& path, size_t max_bytes) {
  try {
    ws::ReadBoundedFile(path, max_bytes);
  } catch (const ws::BoundedFileError& e) {
    return e.what();
  }
  return "";
}

TEST(BoundedFile, OnlyARegularFileWithinItsSizeIsRead) {
  const std::string dir = ws::test::TempDir("bounded-file");
  std::ofstream(dir + "/small.txt") << "0123456789";
  EXPECT_EQ(ws::ReadBoundedFile(dir + "/small.txt", 10), "0123456789");
  EXPECT_EQ(RefusalOf(dir + "/small.txt", 9), "10 bytes: more than 9 bytes, larger than such a file can be");
  ASSERT_EQ(mkfifo((dir + "/fifo").c_str(), 0600), 0);
  EXPECT_EQ(RefusalOf(dir + "/fifo", 1 << 20), "not a regular file (a folder, a FIFO or a device)");
  EXPECT_EQ(RefusalOf("/dev/zero", 1 << 20), "not a regular file (a folder, a FIFO or a device)");
  EXPECT_EQ(RefusalOf(dir, 1 << 20), "not a regular file (a folder, a FIFO or a device)");
  EXPECT_EQ(RefusalOf(dir + "/missing", 1 << 20), "cannot open the file");
}

// A rig folder of mrcal models whose camera-0 is a FIFO: refused, not a hang.
TEST(BoundedFile, AFifoInARigFolderIsRefusedNotWaitedOn) {
  const std::string dir = ws::test::TempDir("bounded-file-rig");
  ASSERT_EQ(mkfifo((dir + "/camera-0.cameramodel").c_str(), 0600), 0);
  std::ofstream(dir + "/camera-1.cameramodel") << "{}";
  try {
    ws::LoadAnyRig(dir);
    FAIL() << "a FIFO loaded";
  } catch (const ws::CalibrationFileError& e) {
    EXPECT_NE(std::string(e.what()).find("camera-0.cameramodel: (file): not a regular file"), std::string::npos)
        << e.what();
  }
}

}  // namespace
