// stereo-capture --source dir: over real LCM: pairs found by name, in order,
// frame ids counting every pair, exit at the end; bad directories are errors.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "lcm_io/channels.h"
#include "lcm_io/image_codec.h"
#include "source/dir_source.h"
#include "source/image_folder.h"
#include "test_support.h"
#include "widestereo/process_status_t.hpp"
#include "widestereo/stereo_frame_t.hpp"

namespace {

using namespace ws::test;

void WriteImage(const std::string& path, int value, int width = 32, int height = 24) {
  cv::imwrite(path, cv::Mat(height, width, CV_8UC1, cv::Scalar(value)));
}

// Pair 1 readable, pair 2 with a left image that is no PNG.
void WriteReadableThenUnreadablePair(const std::string& dir) {
  WriteImage(dir + "/left1.png", 1);
  WriteImage(dir + "/right1.png", 1);
  std::ofstream(dir + "/left2.png") << "not a png";
  WriteImage(dir + "/right2.png", 2);
}

std::string Name(const std::string& path) { return std::filesystem::path(path).filename().string(); }

TEST(ImageFolder, PairsNamesThatDifferOnlyInLeftAndRightAndNamesTheImagesAlone) {
  const std::string dir = TempDir("pairs");
  WriteImage(dir + "/left_03.png", 3);
  WriteImage(dir + "/right_03.png", 103);
  WriteImage(dir + "/left_01.png", 1);
  WriteImage(dir + "/right_01.png", 101);
  WriteImage(dir + "/left_02.png", 2);  // no right: not a pair
  std::ofstream(dir + "/notes_left.txt") << "not an image";
  const ws::ImageFolder folder = ws::FindImageFolder(dir);
  EXPECT_EQ(folder.layout, ws::FolderLayout::kLeftRightNames);
  ASSERT_EQ(folder.pairs.size(), 2u);
  EXPECT_EQ(Name(folder.pairs[0].left), "left_01.png");
  EXPECT_EQ(Name(folder.pairs[0].right), "right_01.png");
  EXPECT_EQ(Name(folder.pairs[1].right), "right_03.png");
  ASSERT_EQ(folder.unpaired.size(), 1u);
  EXPECT_EQ(Name(folder.unpaired[0]), "left_02.png");
}

TEST(ImageFolder, SubfoldersPairByNameAndAFolderOfPlainImagesIsOneCamera) {
  const std::string dir = TempDir("layouts");
  for (const char* side : {"left", "right"}) std::filesystem::create_directories(dir + "/lr/" + side);
  WriteImage(dir + "/lr/left/0001.png", 1);
  WriteImage(dir + "/lr/right/0001.png", 2);
  WriteImage(dir + "/lr/right/0002.png", 3);
  for (const char* cam : {"cam0/data", "cam1/data"}) std::filesystem::create_directories(dir + "/cam/" + cam);
  WriteImage(dir + "/cam/cam0/data/17.png", 1);
  WriteImage(dir + "/cam/cam1/data/17.png", 2);
  std::filesystem::create_directories(dir + "/one");
  WriteImage(dir + "/one/a.png", 1);
  WriteImage(dir + "/one/b.png", 2);

  const ws::ImageFolder lr = ws::FindImageFolder(dir + "/lr");
  EXPECT_EQ(lr.layout, ws::FolderLayout::kLeftRightFolders);
  ASSERT_EQ(lr.pairs.size(), 1u);
  EXPECT_EQ(ws::ImageName(lr.pairs[0].right, dir + "/lr"), "right/0001.png");
  ASSERT_EQ(lr.unpaired.size(), 1u);
  EXPECT_EQ(ws::ImageName(lr.unpaired[0], dir + "/lr"), "right/0002.png");
  const ws::ImageFolder cam = ws::FindImageFolder(dir + "/cam");
  EXPECT_EQ(cam.layout, ws::FolderLayout::kCamFolders);
  EXPECT_EQ(cam.pairs.size(), 1u);
  const ws::ImageFolder one = ws::FindImageFolder(dir + "/one");
  EXPECT_EQ(one.layout, ws::FolderLayout::kOneCamera);
  EXPECT_EQ(one.pairs.size(), 2u);
  // stereo-capture's dir: source asks for --mono there.
  try {
    ws::DirSource source(dir + "/one", false);
    ADD_FAILURE() << "a folder of one camera's images is no stereo source";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("--mono"), std::string::npos) << e.what();
  }
}

TEST(ImageFolder, EmptyOrMissingFolderIsAClearError) {
  EXPECT_THROW(ws::FindImageFolder(TempDir("none")), std::runtime_error);
  EXPECT_THROW(ws::FindImageFolder("/nonexistent/dir"), std::runtime_error);
}

// A folder where no pair reads is an error, not a capture of nothing.
TEST(CaptureDir, NothingReadableExitsNonZero) {
  const std::string dir = TempDir("garbage");
  std::ofstream(dir + "/left01.jpg") << "not a jpeg";
  std::ofstream(dir + "/right01.jpg") << "not a jpeg";
  const auto r = RunCommand({"stereo-capture", "--source", "dir:" + dir, "--log-dir", dir, "--out-url",
                             "file://" + dir + "/images.lcmlog?mode=w"},
                            60);
  EXPECT_NE(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("nothing in " + dir + " could be read"), std::string::npos) << r.output;
}

TEST(CaptureDir, PublishesEveryOpenCvDocPairToALogAndExits) {
  const std::string dir = TempDir("capture");
  const auto r = RunCommand({"stereo-capture", "--source", "dir:" + OpenCvStereoSetDir(), "--frame-clock",
                             "--log-dir", dir, "--out-url", "file://" + dir + "/images.lcmlog?mode=w"},
                            60);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto frames = Messages<widestereo::stereo_frame_t>(ReadLog(dir + "/images.lcmlog"),
                                                           ws::channel::kStereoImages);
  ASSERT_EQ(frames.size(), 13u);  // left01..left14 without 10
  for (size_t i = 0; i < frames.size(); ++i) {
    EXPECT_EQ(frames[i].frame_id, int64_t(i));
    EXPECT_EQ(frames[i].utime, int64_t(i + 1) * 100000);
  }
  // Pair 0 is left01.jpg / right01.jpg, pixel for pixel.
  const cv::Mat left01 = cv::imread(std::string(kOpenCvDataDir) + "/left01.jpg", cv::IMREAD_UNCHANGED);
  const cv::Mat right01 = cv::imread(std::string(kOpenCvDataDir) + "/right01.jpg", cv::IMREAD_UNCHANGED);
  EXPECT_EQ(cv::norm(ws::ImageToMat(frames[0].left), left01, cv::NORM_INF), 0);
  EXPECT_EQ(cv::norm(ws::ImageToMat(frames[0].right), right01, cv::NORM_INF), 0);
}

TEST(CaptureDir, CountAndCompressionAreApplied) {
  const std::string dir = TempDir("count");
  const auto r = RunCommand({"stereo-capture", "--source", "dir:" + OpenCvStereoSetDir(), "--count", "3",
                             "--compression", "png", "--log-dir", dir, "--out-url",
                             "file://" + dir + "/images.lcmlog?mode=w"},
                            60);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto frames = Messages<widestereo::stereo_frame_t>(ReadLog(dir + "/images.lcmlog"),
                                                           ws::channel::kStereoImages);
  ASSERT_EQ(frames.size(), 3u);
  EXPECT_EQ(frames[2].left.pixelformat, widestereo::image_t::PIXEL_FORMAT_PNG);
  EXPECT_EQ(ws::ImageToMat(frames[2].left).size(), cv::Size(640, 480));
}

TEST(CaptureDir, UnreadablePairLeavesAFrameIdGapAndIsCounted) {
  const std::string dir = TempDir("unreadable");
  WriteReadableThenUnreadablePair(dir);
  WriteImage(dir + "/left3.png", 3);
  WriteImage(dir + "/right3.png", 3, 16, 24);  // size differs from left3
  WriteImage(dir + "/left4.png", 4);
  WriteImage(dir + "/right4.png", 4);
  const auto r = RunCommand({"stereo-capture", "--source", "dir:" + dir, "--log-dir", dir,
                             "--out-url", "file://" + dir + "/images.lcmlog?mode=w"},
                            60);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto events = ReadLog(dir + "/images.lcmlog");
  const auto frames = Messages<widestereo::stereo_frame_t>(events, ws::channel::kStereoImages);
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0].frame_id, 0);
  EXPECT_EQ(frames[1].frame_id, 3);
  const auto c = LastCounters(dir + "/images.lcmlog", "stereo-capture", "dir:" + dir);
  EXPECT_EQ(c.received, 2);
  EXPECT_EQ(c.rejected, 2);
}

TEST(DirSource, LoopServesLaterLapsFromTheFirstLapsImagesAndCountsThemAlike) {
  const std::string dir = TempDir("loop");
  WriteReadableThenUnreadablePair(dir);
  ws::DirSource source(dir, true);
  std::vector<ws::StereoPair> lap;
  for (int i = 0; i < 2; ++i) lap.push_back(*source.Next());
  // Later laps: the same pixels without reading the files (now gone).
  std::filesystem::remove(dir + "/left1.png");
  std::filesystem::remove(dir + "/right1.png");
  for (int i = 0; i < 4; ++i) {
    const ws::StereoPair pair = *source.Next();
    const ws::StereoPair& first = lap[size_t(i % 2)];
    EXPECT_EQ(pair.label, first.label);
    ASSERT_EQ(pair.left.empty(), first.left.empty()) << pair.label;
    if (!pair.left.empty()) {
      EXPECT_EQ(cv::norm(pair.left, first.left, cv::NORM_INF), 0);
    }
  }
  const auto counts = source.Counters().at("dir:" + dir);
  EXPECT_EQ(counts.received, 3);  // pair 1 in each of the 3 laps
  EXPECT_EQ(counts.rejected, 3);  // pair 2 likewise
}

// The peak resident memory of this process, bytes (/proc/self/status VmHWM).
int64_t PeakRss() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::stoll(line.substr(6)) * 1024;
  return -1;
}

// A JPEG of 32 x 24 whose frame header claims `side` x `side` pixels: 2 KB
// that cv::imread would decode into side^2 bytes.
void WriteJpegClaiming(const std::string& path, int side) {
  std::vector<uint8_t> bytes;
  cv::imencode(".jpg", cv::Mat(24, 32, CV_8UC1, cv::Scalar(9)), bytes);
  for (size_t i = 0; i + 9 < bytes.size(); ++i)
    if (bytes[i] == 0xFF && bytes[i + 1] == 0xC0) {
      bytes[i + 5] = bytes[i + 7] = uint8_t(side >> 8);
      bytes[i + 6] = bytes[i + 8] = uint8_t(side & 0xFF);
      break;
    }
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

// Every image is sized from its header before it is decoded: a bomb, a FIFO,
// a symlink loop and a pair of another size than most (first in the folder)
// are named and left out, at no cost of memory; 16-bit colour with alpha
// comes as 8-bit colour; the good pairs all come.
TEST(DirSource, SizesImagesFromTheirHeadersAndNamesWhatItLeavesOut) {
  const std::string dir = TempDir("hostile-folder");
  WriteImage(dir + "/left0.png", 1, 64, 48);  // the odd size, first in the folder
  WriteImage(dir + "/right0.png", 1, 64, 48);
  for (int i : {1, 5, 6, 7}) {
    WriteImage(dir + "/left" + std::to_string(i) + ".png", i);
    WriteImage(dir + "/right" + std::to_string(i) + ".png", i);
  }
  WriteJpegClaiming(dir + "/left2.jpg", 32000);
  WriteImage(dir + "/right2.jpg", 2);
  cv::imwrite(dir + "/left3.png", cv::Mat(24, 32, CV_16UC4, cv::Scalar(30000, 20000, 10000, 65535)));
  cv::imwrite(dir + "/right3.png", cv::Mat(24, 32, CV_16UC4, cv::Scalar(30000, 20000, 10000, 65535)));
  ASSERT_EQ(mkfifo((dir + "/left4.png").c_str(), 0644), 0);
  WriteImage(dir + "/right4.png", 4);
  std::filesystem::create_symlink("left8.png", dir + "/left8.png");  // a loop
  WriteImage(dir + "/right8.png", 8);

  ws::DirSource source(dir, false);
  std::vector<std::string> refused;
  int readable = 0;
  while (const auto pair = source.Next()) {
    if (pair->left.empty()) {
      refused.push_back(pair->label);
      continue;
    }
    ++readable;
    EXPECT_EQ(pair->left.size(), cv::Size(32, 24)) << pair->label;
    if (pair->label.find("left3") != std::string::npos) {
      EXPECT_EQ(pair->left.type(), CV_8UC3) << "16-bit colour";
    }
  }
  EXPECT_EQ(readable, 5);  // 1, 3, 5, 6, 7
  const std::vector<std::string> reasons = {"left0.png: 64x48, where 5 of the folder's pairs are 32x24",
                                            "left2.jpg: 32000x32000 pixels, more than",
                                            "left4.png: not a regular file",
                                            "left8.png: Too many levels of symbolic links"};
  ASSERT_EQ(refused.size(), reasons.size()) << ::testing::PrintToString(refused);
  for (size_t i = 0; i < reasons.size(); ++i)
    EXPECT_EQ(refused[i].rfind(reasons[i], 0), 0u) << refused[i] << "\n expected: " << reasons[i];
  EXPECT_LT(PeakRss(), int64_t(600) << 20) << "the 32000 x 32000 image was decoded";
}

TEST(CaptureDir, BadSourceSpecIsAClearError) {
  const std::string dir = TempDir("badspec");
  for (const std::string spec : {"dir:", "camera:1,2", "dir:/nonexistent"}) {
    const auto r = RunCommand({"stereo-capture", "--source", spec, "--log-dir", dir}, 30);
    EXPECT_EQ(r.exit_code, 1) << spec << ": " << r.output;
    EXPECT_NE(r.output.find("stereo-capture:"), std::string::npos) << r.output;
  }
}

}  // namespace
