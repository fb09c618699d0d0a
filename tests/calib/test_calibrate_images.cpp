// stereo-calibrate --images as a new user runs it: OpenCV's own stereo set
// (opencv-doc) laid out the three ways cameras and tools write folders gives
// the same calibration; nothing reaches the live bus in a batch run; and the
// common first mistakes stop with the advice that fixes them.
#include <gtest/gtest.h>

#include <atomic>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <thread>

#include <lcm/lcm-cpp.hpp>

#include "lcm_io/channels.h"
#include "rig/rig_file.h"
#include "test_support.h"
#include "widestereo/process_status_t.hpp"
#include "widestereo/stereo_calibration_t.hpp"

namespace {

namespace fs = std::filesystem;
using namespace ws::test;

constexpr const char* kBoard = "chessboard:9x6:0.025";

enum class Layout { kOneFolder, kLeftRightFolders, kCamFolders };

// The 13 opencv-doc pairs and the Middlebury aloe pair (no board) as one
// layout, links to the data; returns the folder and the aloe pair's names.
std::string OpenCvFolder(const std::string& dir, Layout layout, std::string* no_board_left = nullptr) {
  const char* sides[2] = {"left", "right"};
  const std::string sub[2] = {layout == Layout::kCamFolders ? "cam0/" : "left/",
                              layout == Layout::kCamFolders ? "cam1/" : "right/"};
  auto name = [&](int side, const std::string& number) {
    return layout == Layout::kOneFolder ? std::string(sides[side]) + number + ".jpg" : sub[side] + number + ".jpg";
  };
  for (int side = 0; side < 2; ++side) {
    if (layout != Layout::kOneFolder) fs::create_directories(dir + "/" + sub[side]);
    for (const auto& entry : fs::directory_iterator(OpenCvStereoSetDir())) {
      const std::string file = entry.path().filename().string();
      if (file.rfind(sides[side], 0) == 0)
        fs::create_symlink(fs::canonical(entry.path()), dir + "/" + name(side, file.substr(std::strlen(sides[side]), 2)));
    }
    fs::create_symlink(std::string(kOpenCvDataDir) + (side == 0 ? "/aloeL.jpg" : "/aloeR.jpg"), dir + "/" + name(side, "15"));
  }
  if (no_board_left) *no_board_left = name(0, "15");
  return dir;
}

CommandResult CalibrateImages(const std::string& images, const std::string& out, std::vector<std::string> extra = {}) {
  std::vector<std::string> argv = {"stereo-calibrate", "--images", images, "--board", kBoard, "--out", out};
  argv.insert(argv.end(), extra.begin(), extra.end());
  return RunCommand(argv, 120);
}

TEST(CalibrateImages, ThreeLayoutsGiveTheSameCalibrationAndNameThePairLeftOut) {
  const std::string root = TempDir("images-layouts");
  std::string reference;
  for (Layout layout : {Layout::kOneFolder, Layout::kLeftRightFolders, Layout::kCamFolders}) {
    const std::string dir = root + "/" + std::to_string(int(layout));
    fs::create_directories(dir + "/images");
    std::string no_board;
    const std::string images = OpenCvFolder(dir + "/images", layout, &no_board);
    const CommandResult run = CalibrateImages(images, dir + "/calib.yaml", {"--model", "poly6"});
    ASSERT_EQ(run.exit_code, 0) << run.output;
    // The aloe pair (no board) is of another size than the 13 others: the
    // rig's size is the one most pairs share, wherever the odd one lies.
    EXPECT_NE(run.output.find("board " + std::string(kBoard) + " found: left 13 of 13, right 13 of 13"),
              std::string::npos)
        << run.output;
    EXPECT_NE(run.output.find(no_board + ": 1282x1110, where 13 of the folder's pairs are 640x480: left out"),
              std::string::npos)
        << run.output;
    EXPECT_NE(run.output.find("Table II"), std::string::npos) << run.output;
    // Where everything went, beside the calibration.
    for (const char* file : {"/calib.yaml", "/calib.report.json", "/calib.corners.lcmlog", "/calib.lcmlog",
                             "/stereo-calibrate.log"}) {
      EXPECT_TRUE(fs::exists(dir + file)) << file;
      EXPECT_NE(run.output.find(dir + file), std::string::npos) << file << "\n" << run.output;
    }
    const std::string calibration = ReadFileText(dir + "/calib.yaml");
    if (reference.empty())
      reference = calibration;
    else
      EXPECT_EQ(calibration, reference) << "layout " << int(layout) << " gave another calibration";
  }
  const ws::Rig file = ws::ReadCalibrationFile(root + "/0/calib.yaml");
  EXPECT_NEAR(file.T.norm(), 0.083, 0.005);  // 25 mm squares: the rig's 8 cm baseline
}

// Counts what a batch run would put on the live bus: LCM's default URL,
// the messages of the calibration and of the process `pid`.
class DefaultBusListener {
 public:
  DefaultBusListener() : thread_([this] { Listen(); }) {}
  ~DefaultBusListener() {
    stop_ = true;
    thread_.join();
  }
  void Watch(int pid) { pid_ = pid; }
  int heard() const { return heard_; }

 private:
  void Listen() {
    lcm::LCM lcm;  // the default URL, as a process without --out-url would use it
    EXPECT_TRUE(lcm.good());
    lcm.subscribeFunction(".*", &DefaultBusListener::OnMessage, this);
    ready_ = true;
    while (!stop_) lcm.handleTimeout(50);
  }
  static void OnMessage(const lcm::ReceiveBuffer* rbuf, const std::string& channel, DefaultBusListener* self) {
    namespace ch = ws::channel;
    if (channel == ch::kStereoCalibration || channel == ch::kCalibrationStatus || channel == ch::kStereoCorners) {
      ++self->heard_;
    } else if (channel == ch::kProcessStatus) {
      widestereo::process_status_t status;
      if (status.decode(rbuf->data, 0, int(rbuf->data_size)) > 0 && status.pid == self->pid_) ++self->heard_;
    }
  }

  std::atomic<bool> stop_{false}, ready_{false};
  std::atomic<int> pid_{-1}, heard_{0};
  std::thread thread_;
};

TEST(CalibrateImages, BatchRunsPutNothingOnTheDefaultBusAndAFailedWritePublishesNothing) {
  const std::string dir = TempDir("images-batch");
  fs::create_directories(dir + "/images");
  const std::string images = OpenCvFolder(dir + "/images", Layout::kOneFolder);
  DefaultBusListener bus;
  auto run = [&](std::vector<std::string> argv) {
    Command command(argv);
    bus.Watch(command.pid());
    return command.Wait(120);
  };
  // The one command, then the offline recipe on the corners it kept.
  CommandResult r = run({"stereo-calibrate", "--images", images, "--board", kBoard, "--out", dir + "/calib.yaml",
                         "--model", "poly6"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = run({"stereo-calibrate", "--once", "--model", "poly6", "--in-url",
           "file://" + dir + "/calib.corners.lcmlog?speed=0", "--out", dir + "/again.yaml", "--log-dir", dir});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("nothing on the live bus"), std::string::npos) << r.output;
  // Its output went to a log beside the calibration instead.
  EXPECT_EQ(Messages<widestereo::stereo_calibration_t>(ReadLog(dir + "/again.lcmlog"), ws::channel::kStereoCalibration)
                .size(),
            1u);
  // A calibration file that cannot be written (its path is a folder) is
  // refused before the process starts: nothing published, no log
  // (test_calibrate_outputs.cpp: a write that fails during the run).
  fs::create_directories(dir + "/folder.yaml");
  r = run({"stereo-calibrate", "--once", "--model", "poly6", "--in-url", "file://" + dir + "/calib.corners.lcmlog?speed=0",
           "--out", dir + "/folder.yaml", "--out-url", "file://" + dir + "/failed.lcmlog?mode=w", "--log-dir", dir});
  EXPECT_NE(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("is a folder"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir + "/failed.lcmlog"));
  EXPECT_EQ(bus.heard(), 0) << "a batch run published on LCM's default URL";
}

// What a user gets for each first mistake: a non-zero exit and the advice.
void ExpectRefused(const CommandResult& r, const std::vector<std::string>& says) {
  EXPECT_NE(r.exit_code, 0) << r.output;
  for (const std::string& text : says) EXPECT_NE(r.output.find(text), std::string::npos) << text << "\n" << r.output;
}

class FirstMistakes : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = TempDir("images-mistakes");
    fs::create_directories(dir_ + "/images");
    images_ = OpenCvFolder(dir_ + "/images", Layout::kOneFolder);
  }
  static inline std::string dir_, images_;
};

TEST_F(FirstMistakes, SquaresCountedInsteadOfInnerCornersNameTheSizeFound) {
  ExpectRefused(RunCommand({"stereo-calibrate", "--images", images_, "--board", "chessboard:10x7:0.025", "--out",
                            dir_ + "/c.yaml"},
                           120),
                {"no 10x7 board in any image; 9x6 boards are found in 26 of 28 images: --board chessboard:9x6:0.025",
                 "inner corners"});
}

TEST_F(FirstMistakes, PartOfALargerBoardIsRefused) {
  ExpectRefused(RunCommand({"stereo-calibrate", "--images", images_, "--board", "chessboard:8x6:0.025", "--out",
                            dir_ + "/c.yaml"},
                           120),
                {"shows a 9x6 board", "--board chessboard:9x6:0.025"});
}

TEST_F(FirstMistakes, MillimetresForMetresAreCaughtByEveryProcessThatTakesABoard) {
  for (const char* process : {"stereo-calibrate", "stereo-detect"}) {
    std::vector<std::string> argv = {process, "--board", "chessboard:9x6:25", "--log-dir", dir_};
    if (std::string(process) == "stereo-calibrate") argv.insert(argv.end(), {"--images", images_, "--out", dir_ + "/c.yaml"});
    ExpectRefused(RunCommand(argv, 60), {"a 25 m square", "is this in millimetres?", "0.025 for 25 mm"});
  }
}

TEST_F(FirstMistakes, AnImageWithoutItsPairIsNamedAndLeftOut) {
  const std::string images = TempDir("images-unpaired");
  for (const auto& entry : fs::directory_iterator(images_))
    if (entry.path().filename() != "right14.jpg") fs::copy_symlink(entry.path(), images + "/" + entry.path().filename().string());
  const CommandResult r = CalibrateImages(images, TempDir("images-unpaired-out") + "/c.yaml", {"--model", "poly6", "--nonradial", "none"});
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("left14.jpg has no partner image: left out"), std::string::npos) << r.output;
}

TEST_F(FirstMistakes, AFolderWhereNothingReadsIsAnError) {
  const std::string images = TempDir("images-garbage");
  std::ofstream(images + "/left01.jpg") << "not an image";
  std::ofstream(images + "/right01.jpg") << "not an image";
  ExpectRefused(CalibrateImages(images, TempDir("images-garbage-out") + "/c.yaml"),
                {"nothing in " + images + " could be read"});
}

TEST_F(FirstMistakes, OptionValuesThatDoNotParseSayWhatTheyTake) {
  ExpectRefused(CalibrateImages(images_, dir_ + "/c.yaml", {"--knots", "aut"}),
                {"knots must be 'auto' or a count from 2 to 64, not 'aut'"});
  ExpectRefused(CalibrateImages(images_, dir_ + "/c.yaml", {"--cv-folds", "five"}), {"--cv-folds", "five"});
  ExpectRefused(RunCommand({"stereo-calibrate", "--images", images_, "--out", dir_ + "/c.yaml"}), {"--images needs --board"});
}

TEST_F(FirstMistakes, ACalibrationFileCutShortSaysSo) {
  // Any calibration file will do: the quickest solve.
  ASSERT_EQ(CalibrateImages(images_, dir_ + "/whole.yaml", {"--model", "poly6", "--nonradial", "none"}).exit_code, 0);
  const std::string text = ReadFileText(dir_ + "/whole.yaml");
  for (size_t length : {text.size() / 3, text.size() * 2 / 3, text.size() - 10}) {
    while (text[length - 1] == '\n') --length;  // cut mid-line, as a write stopped part-way leaves it
    std::ofstream(dir_ + "/cut.yaml", std::ios::trunc) << text.substr(0, length);
    ExpectRefused(RunCommand({"stereo-compare", dir_ + "/cut.yaml", dir_ + "/whole.yaml"}),
                  {dir_ + "/cut.yaml", "the file ends mid-line: it was cut short"});
  }
}

}  // namespace
