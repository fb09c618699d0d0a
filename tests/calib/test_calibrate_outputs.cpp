// stereo-calibrate --images's outputs cannot destroy (docs/security.md,
// "Output files"): an --out that would overwrite an image, a foreign file or
// a folder, or follow a symlink, is refused before any work; a write that
// fails part-way leaves the old calibration and report whole; a failed run
// leaves nothing behind.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "test_support.h"

namespace {

namespace fs = std::filesystem;
using namespace ws::test;

constexpr const char* kBoard = "chessboard:9x6:0.025";

// The 13 opencv-doc pairs, linked into a new folder.
std::string OpenCvPairs(const std::string& name) {
  const std::string dir = TempDir(name);
  for (const auto& entry : fs::directory_iterator(OpenCvStereoSetDir())) {
    const std::string file = entry.path().filename().string();
    if (file.rfind("left", 0) == 0 || file.rfind("right", 0) == 0)
      fs::create_symlink(fs::canonical(entry.path()), dir + "/" + file);
  }
  return dir;
}

CommandResult Calibrate(const std::string& images, const std::string& out) {
  return RunCommand({"stereo-calibrate", "--images", images, "--board", kBoard, "--out", out, "--model", "poly6",
                     "--nonradial", "none"},
                    120);
}

void ExpectRefusedBeforeWork(const CommandResult& r, const std::string& says, const std::string& out_dir) {
  EXPECT_NE(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find(says), std::string::npos) << says << "\n" << r.output;
  EXPECT_EQ(r.output.find("finding the board"), std::string::npos) << "refused only after work:\n" << r.output;
  for (const auto& entry : fs::directory_iterator(out_dir))
    EXPECT_FALSE(entry.path().extension() == ".lcmlog" && !entry.is_symlink()) << "a log left behind: " << entry.path();
}

TEST(CalibrateOutputs, AnOutThatWouldDestroyIsRefusedBeforeAnyWork) {
  const std::string images = OpenCvPairs("outputs-images");
  const std::string dir = TempDir("outputs-refused");
  const std::string image = ReadFileText(images + "/left01.jpg");

  // An input image, by its own name or as the folder's calibration.
  ExpectRefusedBeforeWork(Calibrate(images, images + "/left01.jpg"), "a calibration file ends in .yaml", dir);
  ExpectRefusedBeforeWork(Calibrate(images, images + "/calib.yaml"), "is inside the image folder", dir);
  EXPECT_EQ(ReadFileText(images + "/left01.jpg"), image);
  EXPECT_FALSE(fs::exists(images + "/calib.yaml"));

  // A file that is not a widestereo calibration.
  std::ofstream(dir + "/notes.yaml") << "my notes\n";
  ExpectRefusedBeforeWork(Calibrate(images, dir + "/notes.yaml"), "is not a widestereo calibration", dir);
  EXPECT_EQ(ReadFileText(dir + "/notes.yaml"), "my notes\n");

  // A folder.
  fs::create_directories(dir + "/folder.yaml");
  ExpectRefusedBeforeWork(Calibrate(images, dir + "/folder.yaml"), "is a folder", dir);

  // A symlink where an output goes: never followed.
  const std::string victim = TempDir("outputs-victim") + "/victim.lcmlog";
  std::ofstream(victim) << "someone's log\n";
  fs::create_symlink(victim, dir + "/c.lcmlog");
  ExpectRefusedBeforeWork(Calibrate(images, dir + "/c.yaml"), "is a symlink", dir);
  EXPECT_EQ(ReadFileText(victim), "someone's log\n");
}

// The disk fills while the report is written (a file size limit stands in
// for it: EFBIG where ENOSPC would be): the run fails naming the file, and
// the calibration, report and corners of the run before stand, whole.
TEST(CalibrateOutputs, AWriteThatFailsLeavesTheOldSetWhole) {
  const std::string images = OpenCvPairs("outputs-full-images");
  const std::string dir = TempDir("outputs-full");
  ASSERT_EQ(Calibrate(images, dir + "/c.yaml").exit_code, 0);
  const std::string yaml = ReadFileText(dir + "/c.yaml"), report = ReadFileText(dir + "/c.report.json"),
                    messages = ReadFileText(dir + "/c.lcmlog");
  ASSERT_LT(yaml.size() + 4096, report.size()) << "the limit must fall between the two files";
  // Corners unlike those this run finds: the old ones must stand all the same.
  fs::copy_file(dir + "/c.lcmlog", dir + "/c.corners.lcmlog", fs::copy_options::overwrite_existing);

  rlimit before;
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &before), 0);
  const auto handler = std::signal(SIGXFSZ, SIG_IGN);  // inherited: the write fails instead
  rlimit small = before;
  small.rlim_cur = yaml.size() + 4096;
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &small), 0);
  const CommandResult r = RunCommand({"stereo-calibrate", "--images", images, "--board", kBoard, "--out",
                                      dir + "/c.yaml", "--model", "kb4", "--nonradial", "none"},
                                     120);
  setrlimit(RLIMIT_FSIZE, &before);
  std::signal(SIGXFSZ, handler);

  EXPECT_NE(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("cannot write '" + dir + "/c."), std::string::npos) << r.output;
  EXPECT_EQ(ReadFileText(dir + "/c.yaml"), yaml) << "the old calibration must stand";
  EXPECT_EQ(ReadFileText(dir + "/c.report.json"), report) << "the old report must stand";
  EXPECT_EQ(ReadFileText(dir + "/c.lcmlog"), messages) << "the old messages' log must stand";
  EXPECT_EQ(ReadFileText(dir + "/c.corners.lcmlog"), messages) << "the old corners' log must stand";
  for (const auto& entry : fs::directory_iterator(dir)) {
    EXPECT_EQ(entry.path().string().find(".tmp."), std::string::npos) << "a temporary left: " << entry.path();
    EXPECT_NE(entry.path().extension(), ".partial") << "a pending log left: " << entry.path();
  }
}

TEST(CalibrateOutputs, AFailedRunLeavesNothingBehind) {
  const std::string images = TempDir("outputs-garbage");
  std::ofstream(images + "/left01.jpg") << "not an image";
  std::ofstream(images + "/right01.jpg") << "not an image";
  const std::string dir = TempDir("outputs-nothing");
  const CommandResult r = Calibrate(images, dir + "/c.yaml");
  EXPECT_NE(r.exit_code, 0) << r.output;
  std::vector<std::string> left;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().filename() != "stereo-calibrate.log") left.push_back(entry.path().filename().string());
  EXPECT_TRUE(left.empty()) << "left behind: " << ::testing::PrintToString(left);
}

// Hostile files in the folder are named and left out, on the terminal and
// in stereo-calibrate.log, and the run goes on with the good pairs: a
// JPEG whose header claims 60000 x 60000 pixels, a FIFO, a symlink loop.
TEST(CalibrateOutputs, HostileImagesAreNamedAndLeftOutAndTheRunGoesOn) {
  const std::string images = OpenCvPairs("outputs-hostile-images");
  std::vector<uint8_t> jpeg;
  cv::imencode(".jpg", cv::Mat(24, 32, CV_8UC1, cv::Scalar(9)), jpeg);
  for (size_t i = 0; i + 9 < jpeg.size(); ++i)
    if (jpeg[i] == 0xFF && jpeg[i + 1] == 0xC0) {
      jpeg[i + 5] = jpeg[i + 7] = uint8_t(60000 >> 8);
      jpeg[i + 6] = jpeg[i + 8] = uint8_t(60000 & 0xFF);
      break;
    }
  std::ofstream(images + "/left90.jpg", std::ios::binary)
      .write(reinterpret_cast<const char*>(jpeg.data()), std::streamsize(jpeg.size()));
  fs::copy_file(fs::canonical(images + "/right01.jpg"), images + "/right90.jpg");
  ASSERT_EQ(mkfifo((images + "/left91.jpg").c_str(), 0644), 0);
  fs::copy_file(fs::canonical(images + "/right01.jpg"), images + "/right91.jpg");
  fs::create_symlink("left92.jpg", images + "/left92.jpg");
  fs::copy_file(fs::canonical(images + "/right01.jpg"), images + "/right92.jpg");

  const std::string dir = TempDir("outputs-hostile");
  const CommandResult r = Calibrate(images, dir + "/c.yaml");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string log = ReadFileText(dir + "/stereo-calibrate.log");
  for (const std::string& says : {std::string("left90.jpg: 60000x60000 pixels, more than"),
                                  std::string("left91.jpg: not a regular file"),
                                  std::string("left92.jpg: Too many levels of symbolic links"),
                                  std::string("found: left 13 of 13, right 13 of 13")}) {
    EXPECT_NE(r.output.find(says), std::string::npos) << says << "\n" << r.output;
    EXPECT_NE(log.find(says), std::string::npos) << says << " not in the log";
  }
}

// Where no image shows the board, the advice tries other sizes on the
// folder's images: never on one it left out (a FIFO would block the run,
// a bomb take gigabytes).
TEST(CalibrateOutputs, NoBoardAdviceNeverOpensWhatTheFolderLeftOut) {
  const std::string images = TempDir("outputs-noboard-images");
  for (const char* side : {"left", "right"})
    for (int i = 1; i <= 3; ++i)
      cv::imwrite(images + "/" + side + std::to_string(i) + ".png", cv::Mat(240, 320, CV_8UC1, cv::Scalar(40 * i)));
  ASSERT_EQ(mkfifo((images + "/left4.png").c_str(), 0644), 0);
  cv::imwrite(images + "/right4.png", cv::Mat(240, 320, CV_8UC1, cv::Scalar(9)));
  const CommandResult r = Calibrate(images, TempDir("outputs-noboard") + "/c.yaml");
  EXPECT_NE(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("left4.png: not a regular file"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("no 9x6 board in any image"), std::string::npos) << r.output;
}

}  // namespace
