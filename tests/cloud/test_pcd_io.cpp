// Point clouds through binary PCD files.
#include <gtest/gtest.h>

#include <fstream>

#include "cloud/pcd_io.h"
#include "cloud_test_support.h"

namespace {

using ws::testing::MakeCloud;
using ws::testing::ScratchFile;

// The PCD header, up to and including its DATA line.
std::string Header(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line, header;
  while (std::getline(in, line) && header.find("DATA") == std::string::npos) header += line + "\n";
  return header;
}

TEST(Pcd, BinaryRoundTripKeepsPointsAndIntensity) {
  const auto msg = MakeCloud({{0.1f, -0.2f, 2.5f}, {1e-7f, 3e4f, -1}, {0, 0, 10000}}, {1, 2.5f, 0});
  const ScratchFile file("with_intensity.pcd");
  const std::string& path = file.path();
  ws::WritePcd(path, msg);
  const std::string header = Header(path);
  EXPECT_NE(header.find("FIELDS x y z intensity\n"), std::string::npos) << header;
  EXPECT_NE(header.find("DATA binary\n"), std::string::npos) << header;
  const auto back = ws::ReadPcd(path);
  EXPECT_EQ(back.npoints, 3);
  EXPECT_EQ(back.xyz, msg.xyz);  // binary: bit for bit
  EXPECT_EQ(back.nintensity, 3);
  EXPECT_EQ(back.intensity, msg.intensity);
}

TEST(Pcd, CloudWithoutIntensityHasXyzOnly) {
  const auto msg = MakeCloud({{1, 2, 3}});
  const ScratchFile file("xyz.pcd");
  const std::string& path = file.path();
  ws::WritePcd(path, msg);
  EXPECT_NE(Header(path).find("FIELDS x y z\n"), std::string::npos) << Header(path);
  const auto back = ws::ReadPcd(path);
  EXPECT_EQ(back.xyz, msg.xyz);
  EXPECT_EQ(back.nintensity, 0);
  EXPECT_TRUE(back.intensity.empty());
}

TEST(Pcd, EmptyCloudRoundTrips) {
  const ScratchFile file("empty.pcd");
  ws::WritePcd(file.path(), MakeCloud({}));
  EXPECT_EQ(ws::ReadPcd(file.path()).npoints, 0);
}

TEST(Pcd, ErrorsNameThePath) {
  const auto msg = MakeCloud({{1, 2, 3}});
  try {
    ws::WritePcd("/nonexistent/dir/cloud.pcd", msg);
    FAIL() << "wrote";
  } catch (const ws::PcdError& e) {
    EXPECT_NE(std::string(e.what()).find("'/nonexistent/dir/cloud.pcd'"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(ws::ReadPcd("/nonexistent/cloud.pcd"), ws::PcdError);
  const ScratchFile not_pcd("not.pcd", "hello\n");
  EXPECT_THROW(ws::ReadPcd(not_pcd.path()), ws::PcdError);
}

// Found by tests/fuzz: on this header (a NUL after DATA) PCL 1.13 throws
// std::out_of_range, which ReadPcd let through.
TEST(Pcd, MalformedHeaderIsAPcdError) {
  using namespace std::string_literals;
  const ScratchFile bad("bad.pcd", "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n"
                                   "WIDTH 40\nHEIGHT 1\nPOINTS 40\nDATA\0binary_compressed\n"s);
  try {
    ws::ReadPcd(bad.path());
    ADD_FAILURE() << "read a PCD with a broken header";
  } catch (const ws::PcdError& e) {
    EXPECT_NE(std::string(e.what()).find(bad.path()), std::string::npos) << e.what();
  }
}

// Found by tests/fuzz (AddressSanitizer): PCL takes SIZE from the header and
// copies 4-byte floats regardless, reading past the data of the last point.
TEST(Pcd, FieldSizesThatDisagreeWithTheirTypesAreAPcdError) {
  std::string text = "VERSION 0.7\nFIELDS x y z intensity\nSIZE 3 4 4 1\nPOINTS 40\nDATA binary\n";
  text += std::string(320, '\x01');
  const ScratchFile bad("sizes.pcd", text);
  try {
    ws::ReadPcd(bad.path());
    ADD_FAILURE() << "read a PCD whose x is 3 bytes";
  } catch (const ws::PcdError& e) {
    EXPECT_NE(std::string(e.what()).find("the fields' SIZE disagrees with their TYPE and COUNT"), std::string::npos) << e.what();
  }
}

// Found by tests/fuzz (AddressSanitizer: out of memory): PCL's readHeader
// allocates what WIDTH, HEIGHT, SIZE and COUNT announce before it reads.
TEST(Pcd, HeaderAnnouncingTooMuchIsAPcdError) {
  const std::string header = "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\n";
  for (const auto& [lines, reason] : std::vector<std::pair<std::string, std::string>>{
           {"COUNT 1 1222222222222222222222222222222222222222222222222222222222222222222222 1\nWIDTH 40\n",
            "COUNT '1222222222222222222222222222222222222222222222222222222222222222222222' is not a whole number"},
           {"COUNT 1 1 1\nWIDTH 100000000\nHEIGHT 100\n", "announces 10000000000 points of 12 bytes"},
           {"COUNT 1 -1 1\nWIDTH 40\n", "COUNT '-1' is not a whole number"}}) {
    const ScratchFile bad("announces.pcd", header + lines + "DATA binary\n" + std::string(480, '\0'));
    try {
      ws::ReadPcd(bad.path());
      ADD_FAILURE() << "read a PCD with " << lines;
    } catch (const ws::PcdError& e) {
      EXPECT_NE(std::string(e.what()).find(reason), std::string::npos) << e.what();
    }
  }
}

// Found by tests/fuzz (a segfault in PCL): a compressed body announcing 0
// bytes for 40 points; and a raw body shorter than its points.
TEST(Pcd, BodyThatDoesNotHoldItsPointsIsAPcdError) {
  using namespace std::string_literals;
  const std::string header = "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 40\n"
                             "HEIGHT 1\nPOINTS 40\nDATA ";
  const ScratchFile compressed("compressed.pcd", header + "binary_compressed\n" + "\x04\0\0\0\0\0\0\0abcd"s);
  const ScratchFile raw("raw.pcd", header + "binary\n" + std::string(100, '\x01'));  // 480 bytes due
  for (const ScratchFile* file : {&compressed, &raw}) {
    try {
      ws::ReadPcd(file->path());
      ADD_FAILURE() << "read " << file->path();
    } catch (const ws::PcdError& e) {
      EXPECT_NE(std::string(e.what()).find(file->path()), std::string::npos) << e.what();
    }
  }
}

}  // namespace
