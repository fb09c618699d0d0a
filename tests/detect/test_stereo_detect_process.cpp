// stereo-detect as a real process over real LCM: the opencv-doc pairs from
// stereo-capture's dir: source replayed log to log, the same output on every
// replay, bad images rejected or published empty, and live over udpm, frames
// it cannot keep up with dropped and counted while its memory stays bounded.
#include <gtest/gtest.h>
#include <signal.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <thread>

#include <lcm/lcm-cpp.hpp>
#include <opencv2/imgcodecs.hpp>

#include "board/board_spec.h"
#include "detect/synthetic_view.h"
#include "detect_test_views.h"
#include "lcm_io/channels.h"
#include "lcm_io/image_codec.h"
#include "test_support.h"
#include "widestereo/process_status_t.hpp"
#include "widestereo/stereo_corners_t.hpp"
#include "widestereo/stereo_frame_t.hpp"

namespace {

using namespace ws::test;
using widestereo::channel_counters_t;
using widestereo::process_status_t;
using widestereo::stereo_corners_t;
using widestereo::stereo_frame_t;

std::string FileUrl(const std::string& path, const std::string& mode) {
  return "file://" + path + "?" + mode;
}

// stereo-detect from `in` (a log) to `out` (a log), with `extra` options.
CommandResult Detect(const std::string& dir, const std::string& in, const std::string& out,
                     std::vector<std::string> extra = {}) {
  std::vector<std::string> argv = {"stereo-detect", "--log-dir", dir, "--in-url", FileUrl(in, "speed=0"),
                                   "--out-url", FileUrl(out, "mode=w")};
  argv.insert(argv.end(), extra.begin(), extra.end());
  return RunCommand(argv, 60);
}

channel_counters_t LastCounters(const std::vector<LogEvent>& events, const std::string& channel) {
  const auto statuses = Messages<process_status_t>(events, ws::channel::kProcessStatus);
  if (!statuses.empty())
    for (const auto& c : statuses.back().channels)
      if (c.channel == channel) return c;
  ADD_FAILURE() << "no counters of " << channel;
  return {};
}

class StereoDetectReplay : public ::testing::Test {
 protected:
  // The 13 opencv-doc pairs as stereo-capture publishes them, once for the
  // suite (from a folder of links: the opencv-doc folder has another pair,
  // left.jpg and right.jpg, that is not a board).
  static void SetUpTestSuite() {
    dir_ = new std::string(TempDir("detect-replay"));
    const std::string pairs = *dir_ + "/pairs";
    std::filesystem::create_directory(pairs);
    for (int index : kOpenCvDocPairs)
      for (const std::string side : {"left", "right"})
        std::filesystem::create_symlink(kOpenCvData + "/" + OpenCvDocName(side, index),
                                        pairs + "/" + OpenCvDocName(side, index));
    const auto r = RunCommand({"stereo-capture", "--source", "dir:" + pairs, "--frame-clock",
                               "--log-dir", *dir_, "--out-url", FileUrl(images(), "mode=w")},
                              60);
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  static void TearDownTestSuite() { delete dir_; }
  static std::string images() { return *dir_ + "/images.lcmlog"; }
  static std::string* dir_;
};
std::string* StereoDetectReplay::dir_ = nullptr;

void ExpectWholeBoard(const widestereo::camera_corners_t& camera, const ws::BoardSpec& board) {
  EXPECT_EQ(camera.board_id, board.id);
  EXPECT_EQ(camera.image_width, 640);
  EXPECT_EQ(camera.image_height, 480);
  ASSERT_EQ(camera.n, 54);
  for (int i = 0; i < camera.n; ++i) {
    EXPECT_EQ(camera.ids[i], i);
    const cv::Point3d object = board.ObjectPoint(i);
    EXPECT_EQ(camera.object_points[i], (std::vector<double>{object.x, object.y, object.z}));
  }
}

TEST_F(StereoDetectReplay, FindsTheBoardInEveryOpenCvDocPairInOrder) {
  const ws::BoardSpec board = ws::ParseBoardSpec("chessboard:9x6:0.025");
  const std::string out = *dir_ + "/corners.lcmlog";
  const auto r = Detect(*dir_, images(), out, {"--board", board.id, "--workers", "2"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto events = ReadLog(out);
  const auto corners = Messages<stereo_corners_t>(events, ws::channel::kStereoCorners);
  const auto frames = Messages<stereo_frame_t>(ReadLog(images()), ws::channel::kStereoImages);
  ASSERT_EQ(corners.size(), 13u);
  for (size_t i = 0; i < corners.size(); ++i) {
    SCOPED_TRACE("frame " + std::to_string(i));
    EXPECT_EQ(corners[i].frame_id, int64_t(i));
    EXPECT_EQ(corners[i].utime, frames[i].utime);
    ExpectWholeBoard(corners[i].left, board);
    ExpectWholeBoard(corners[i].right, board);
  }
  const auto images_in = LastCounters(events, ws::channel::kStereoImages);
  EXPECT_EQ(images_in.received, 13);
  EXPECT_EQ(images_in.dropped, 0);
  EXPECT_EQ(images_in.rejected, 0);
  EXPECT_EQ(LastCounters(events, ws::channel::kStereoCorners).published, 13);
}

// The channels of a log in order, and its STEREO_CORNERS payloads.
std::vector<std::string> ChannelSequence(const std::vector<LogEvent>& events) {
  std::vector<std::string> channels;
  for (const auto& e : events) channels.push_back(e.channel);
  return channels;
}

std::vector<std::vector<uint8_t>> CornerPayloads(const std::vector<LogEvent>& events) {
  std::vector<std::vector<uint8_t>> payloads;
  for (const auto& e : events)
    if (e.channel == ws::channel::kStereoCorners) payloads.push_back(e.data);
  return payloads;
}

TEST_F(StereoDetectReplay, SameLogGivesTheSameOutputEveryTime) {
  std::vector<std::vector<LogEvent>> runs;
  for (int run = 0; run < 2; ++run) {
    const std::string out = *dir_ + "/again" + std::to_string(run) + ".lcmlog";
    const auto r = Detect(*dir_, images(), out, {"--workers", "2", "--max-in-flight", "3"});
    ASSERT_EQ(r.exit_code, 0) << r.output;
    runs.push_back(ReadLog(out));
  }
  EXPECT_EQ(CornerPayloads(runs[0]).size(), 13u);
  EXPECT_EQ(CornerPayloads(runs[0]), CornerPayloads(runs[1]));
  EXPECT_EQ(ChannelSequence(runs[0]), ChannelSequence(runs[1]));  // heartbeats at the same places
}

TEST_F(StereoDetectReplay, ReplayWaitsInsteadOfDroppingWithOneFrameInFlight) {
  const std::string out = *dir_ + "/narrow.lcmlog";
  const auto r = Detect(*dir_, images(), out, {"--workers", "2", "--max-in-flight", "1"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto events = ReadLog(out);
  EXPECT_EQ(Messages<stereo_corners_t>(events, ws::channel::kStereoCorners).size(), 13u);
  EXPECT_EQ(LastCounters(events, ws::channel::kStereoImages).dropped, 0);
}

stereo_frame_t Frame(int64_t frame_id, const widestereo::image_t& left, const widestereo::image_t& right) {
  stereo_frame_t frame{};
  frame.utime = (frame_id + 1) * 100000;
  frame.frame_id = frame_id;
  frame.left = left;
  frame.right = right;
  return frame;
}

widestereo::image_t JpegFile(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  const std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(file)), {});
  widestereo::image_t image = ws::MatToImage(cv::imread(path, cv::IMREAD_UNCHANGED), 0, ws::Compression::jpeg);
  image.data = bytes;  // the file itself, as stereo-capture would send it
  image.size = int32_t(bytes.size());
  return image;
}

TEST(StereoDetectBadInput, NoBoardIsPublishedEmptyBrokenImagesAreRejected) {
  const std::string dir = TempDir("detect-bad");
  const auto left01 = JpegFile(kOpenCvData + "/left01.jpg");
  const auto right01 = JpegFile(kOpenCvData + "/right01.jpg");
  const auto no_board = ws::MatToImage(cv::imread(kOpenCvData + "/left.jpg"), 0);  // a room, in colour
  const auto black = ws::MatToImage(cv::Mat(480, 640, CV_8UC1, cv::Scalar(0)), 0);
  auto truncated = left01;
  truncated.data.resize(truncated.data.size() / 2);
  truncated.size = int32_t(truncated.data.size());
  const auto tiny = ws::MatToImage(cv::Mat(1, 1, CV_8UC1, cv::Scalar(7)), 0);
  const std::string images = ws::channel::kStereoImages;
  WriteLog(dir + "/in.lcmlog", {Event(images, Frame(0, left01, right01)),
                                Event(images, Frame(1, no_board, no_board)),
                                Event(images, Frame(2, black, black)),
                                Event(images, Frame(3, truncated, right01)),
                                Event(images, Frame(4, left01, tiny)),
                                Event(images, Frame(5, left01, right01))});
  const auto r = Detect(dir, dir + "/in.lcmlog", dir + "/out.lcmlog");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto events = ReadLog(dir + "/out.lcmlog");
  const auto corners = Messages<stereo_corners_t>(events, ws::channel::kStereoCorners);
  ASSERT_EQ(corners.size(), 4u);
  const std::vector<int64_t> ids = {corners[0].frame_id, corners[1].frame_id, corners[2].frame_id,
                                    corners[3].frame_id};
  EXPECT_EQ(ids, (std::vector<int64_t>{0, 1, 2, 5}));
  EXPECT_EQ(corners[0].left.n, 54);
  for (int i : {1, 2}) {
    EXPECT_EQ(corners[i].left.n, 0);
    EXPECT_EQ(corners[i].right.n, 0);
    EXPECT_EQ(corners[i].left.image_width, i == 1 ? no_board.width : 640);
  }
  EXPECT_EQ(corners[3].right.n, 54);
  const auto counters = LastCounters(events, images);
  EXPECT_EQ(counters.received, 6);
  EXPECT_EQ(counters.rejected, 2);
  EXPECT_NE(r.output.find("frame 3 rejected: image_t: JPEG payload is cut short"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("frame 4 rejected: a 1x1 image is too small"), std::string::npos) << r.output;
}

TEST(StereoDetectCli, BadBoardSpecIsAClearError) {
  const std::string dir = TempDir("detect-cli");
  const auto r = RunCommand({"stereo-detect", "--log-dir", dir, "--board", "chessboard:9x6"}, 30);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("stereo-detect: board 'chessboard:9x6': chessboard takes 3"), std::string::npos)
      << r.output;
}

// Live over udpm, 1280x960 raw pairs (2.4 MB) arrive at 40 Hz, faster than
// one worker finds boards in them: frames are dropped and counted, the rest
// published in order, and memory grows by the frames in flight and the
// detector's working memory (sb: about 70 MB at this size), not by the 190 MB
// of frames sent.
TEST(StereoDetectLive, DropsAndCountsFramesItCannotKeepUpWith) {
  const std::string dir = TempDir("detect-live");
  const std::string bus = UniqueUdpmUrl(3) + "&recv_buf_size=4194304";  // Linux's default drops most
  CommandResult detect;
  std::thread detect_thread([&] {
    detect = RunCommand({"stereo-detect", "--log-dir", dir, "--in-url", bus, "--out-url", bus,
                         "--chessboard-detector", "sb", "--workers", "1", "--max-in-flight", "2"},
                        60);
  });

  lcm::LCM lcm(bus);
  ASSERT_TRUE(lcm.good());
  std::vector<process_status_t> statuses;
  std::vector<int64_t> published_ids;
  lcm.subscribeFunction(
      ws::channel::kProcessStatus,
      +[](const lcm::ReceiveBuffer* rbuf, const std::string&, std::vector<process_status_t>* out) {
        process_status_t s;
        if (s.decode(rbuf->data, 0, int(rbuf->data_size)) > 0 && s.name == "stereo-detect") out->push_back(s);
      },
      &statuses);
  lcm.subscribeFunction(
      ws::channel::kStereoCorners,
      +[](const lcm::ReceiveBuffer* rbuf, const std::string&, std::vector<int64_t>* out) {
        stereo_corners_t c{};
        if (c.decode(rbuf->data, 0, int(rbuf->data_size)) > 0) out->push_back(c.frame_id);
      },
      &published_ids);
  // Listens until `done` or `seconds` have passed; returns `done`.
  auto listen_until = [&](double seconds, const std::function<bool()>& done) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (!done() && std::chrono::steady_clock::now() < end) lcm.handleTimeout(10);
    return done();
  };
  ASSERT_TRUE(listen_until(10, [&] { return !statuses.empty(); })) << "no heartbeat from stereo-detect";
  const int pid = statuses.back().pid;
  const long resident_before_kb = ResidentKb(pid, "VmRSS");

  const ws::BoardSpec board = ws::ParseBoardSpec("chessboard:9x6:0.025");
  const cv::Size size(1280, 960);
  const auto image = ws::MatToImage(ws::RenderBoard(board, ws::BoardToImage(board, {}, size), {size}).image, 0);
  constexpr int kFrames = 80;
  for (int i = 0; i < kFrames; ++i) {
    const stereo_frame_t frame = Frame(i, image, image);
    lcm.publish(ws::channel::kStereoImages, &frame);
    listen_until(0.025, [] { return false; });
  }
  // Every frame received is eventually published or counted as dropped.
  channel_counters_t in{}, out{};
  const bool accounted = listen_until(30, [&] {
    if (statuses.empty()) return false;
    for (const auto& c : statuses.back().channels) {
      if (c.channel == ws::channel::kStereoImages) in = c;
      if (c.channel == ws::channel::kStereoCorners) out = c;
    }
    return out.published > 0 && out.published == int64_t(published_ids.size()) &&
           in.received - out.published <= in.dropped;
  });
  const long growth_kb = ResidentKb(pid, "VmHWM") - resident_before_kb;
  kill(pid, SIGINT);
  detect_thread.join();
  EXPECT_EQ(detect.exit_code, 0) << "Ctrl-C is a clean stop: " << detect.output;

  std::printf("live: %d pairs sent, %ld received, %ld published, %ld dropped; memory grew %ld MB\n",
              kFrames, long(in.received), long(out.published), long(in.dropped), growth_kb / 1024);
  EXPECT_TRUE(accounted) << "frames neither published nor counted as dropped";
  EXPECT_GE(in.received, 10);
  EXPECT_GT(in.received - out.published, 0);  // it could not keep up
  EXPECT_EQ(in.rejected, 0);
  EXPECT_TRUE(std::is_sorted(published_ids.begin(), published_ids.end()));
  EXPECT_NE(detect.output.find("(peak 2)"), std::string::npos) << detect.output;
  if (kMemoryBoundsMeaningful) {
    EXPECT_LT(growth_kb, 150 * 1024);
  }
}

}  // namespace
