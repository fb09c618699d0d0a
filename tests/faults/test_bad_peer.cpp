// A peer floods every channel a process reads with garbage, truncated,
// wrong-type, invalid and oversized messages while good frames flow, over real udpm:
// the process keeps running, counts every bad message it receives as rejected
// in PROCESS_STATUS, and its output for the good frames is byte for byte what
// a clean replay of the same frames gives; with a rig key and without.
#include <gtest/gtest.h>
#include <signal.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "bad_peer.h"
#include "lcm_io/channels.h"
#include "lcm_io/image_codec.h"
#include "match_fixtures.h"
#include "test_support.h"
#include "widestereo/disparity_t.hpp"
#include "widestereo/stereo_corners_t.hpp"
#include "widestereo/stereo_frame_t.hpp"

namespace {

using namespace ws::test;
using widestereo::stereo_frame_t;
namespace ch = ws::channel;

stereo_frame_t Frame(int64_t id, const cv::Mat& left, const cv::Mat& right, ws::Compression compression) {
  stereo_frame_t frame{};
  frame.frame_id = id;
  frame.utime = (id + 1) * 200000;
  frame.left = ws::MatToImage(left, frame.utime, compression);
  frame.right = ws::MatToImage(right, frame.utime, compression);
  return frame;
}

// A stereo frame whose left image claims 100000 x 1000 pixels.
stereo_frame_t TooLargeFrame(stereo_frame_t frame) {
  frame.left.width = frame.left.row_stride = 100000;
  frame.left.height = 1000;
  return frame;
}

TEST_P(BadPeer, StereoDetectRejectsItAllAndFindsTheSameCorners) {
  const std::string dir = TempDir("faults-detect");
  std::vector<stereo_frame_t> frames;
  std::vector<LogEvent> clean_in;
  for (int i = 1; i <= 3; ++i) {
    const auto image = [&](const char* side) {
      return cv::imread(std::string(kOpenCvDataDir) + "/" + side + "0" + std::to_string(i) + ".jpg",
                        cv::IMREAD_GRAYSCALE);
    };
    frames.push_back(Frame(i - 1, image("left"), image("right"), ws::Compression::jpeg));
    clean_in.push_back(Event(ch::kStereoImages, frames.back()));
  }
  const std::vector<std::string> detect = {"stereo-detect", "--workers", "2", "--max-in-flight", "8"};
  const auto clean = CleanRun(dir, clean_in, detect, ch::kStereoCorners);
  ASSERT_EQ(clean.size(), frames.size());

  const std::string url = UniqueUdpmUrl(11) + "&recv_buf_size=8388608";
  std::vector<std::string> argv = detect;
  argv.insert(argv.end(), {"--log-dir", dir, "--in-url", url, "--out-url", url});
  for (const std::string& arg : KeyArgs(dir)) argv.push_back(arg);
  Command process(argv);
  BusWatch bus(url, "stereo-detect");
  bus.Collect(ch::kStereoCorners);
  ASSERT_TRUE(bus.ListenUntil(20, [&] { return bus.status().has_value(); })) << process.Output();

  BadChannel bad{ch::kStereoImages,
                 BadMessages(Encoded(frames[0]), Encoded(CommandMessage("solve")), Encoded(TooLargeFrame(frames[0])), 7)};
  for (const auto& frame : frames) {
    Flood(bus, {&bad});
    bus.Publish(ch::kStereoImages, AsSent(ch::kStereoImages, frame));
  }
  const int good = int(frames.size());
  const bool settled = bus.ListenUntil(30, [&] {
    const auto c = bus.Counters(ch::kStereoImages);
    return bus.Payloads(ch::kStereoCorners).size() == frames.size() && c.received > 0 &&
           c.received == good + c.rejected && bus.Counters(ch::kStereoCorners).published == good;
  });
  process.Signal(SIGINT);
  const auto r = process.Wait(20);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(settled) << "the counters never accounted for everything sent";
  EXPECT_EQ(WithoutAuth<widestereo::stereo_corners_t>(bus.Payloads(ch::kStereoCorners)), clean);
  ExpectRejectedAllBad(bus, bad, good);
}

TEST_P(BadPeer, StereoMatchRejectsItAllAndMatchesTheSame) {
  const std::string dir = TempDir("faults-match");
  const auto image = [](const char* name) {
    cv::Mat gray = cv::imread(std::string(kOpenCvDataDir) + "/" + name, cv::IMREAD_GRAYSCALE);
    cv::resize(gray, gray, {320, 240}, 0, 0, cv::INTER_AREA);
    return gray;
  };
  const cv::Mat left = image("aloeL.jpg"), right = image("aloeR.jpg");
  auto calibration = IdentityCalibration(320, 240, 300, 0.1);
  calibration.utime = 100000;
  std::vector<stereo_frame_t> frames;
  std::vector<LogEvent> clean_in = {Event(ch::kStereoCalibration, calibration)};
  for (int i = 0; i < 3; ++i) {
    // The same pair shifted by i pixels, so that every frame's output differs.
    const cv::Mat shift = (cv::Mat_<double>(2, 3) << 1, 0, i, 0, 1, 0);
    cv::Mat l, r;
    cv::warpAffine(left, l, shift, left.size());
    cv::warpAffine(right, r, shift, right.size());
    frames.push_back(Frame(i, l, r, ws::Compression::png));
    clean_in.push_back(Event(ch::kStereoImages, frames.back()));
  }
  const std::vector<std::string> match = {"stereo-match", "--num-disparities", "64"};
  const auto clean = CleanRun(dir, clean_in, match, ch::kStereoDisparity);
  ASSERT_EQ(clean.size(), frames.size());

  const std::string url = UniqueUdpmUrl(12) + "&recv_buf_size=8388608";
  std::vector<std::string> argv = match;
  argv.insert(argv.end(), {"--log-dir", dir, "--in-url", url, "--out-url", url});
  for (const std::string& arg : KeyArgs(dir)) argv.push_back(arg);
  Command process(argv);
  BusWatch bus(url, "stereo-match");
  bus.Collect(ch::kStereoDisparity);
  ASSERT_TRUE(bus.ListenUntil(20, [&] { return bus.status().has_value(); })) << process.Output();

  auto too_large_calibration = calibration;
  too_large_calibration.left.image_width = too_large_calibration.right.image_width = 1 << 20;
  BadChannel bad_calibrations{
      ch::kStereoCalibration,
      BadMessages(Encoded(calibration), Encoded(frames[0]), Encoded(too_large_calibration), 8)};
  BadChannel bad_frames{ch::kStereoImages, BadMessages(Encoded(frames[0]), Encoded(calibration),
                                                       Encoded(TooLargeFrame(frames[0])), 9)};
  const std::vector<BadChannel*> both = {&bad_calibrations, &bad_frames};
  Flood(bus, both);
  bus.Publish(ch::kStereoCalibration, AsSent(ch::kStereoCalibration, calibration));
  ASSERT_TRUE(bus.ListenUntil(20, [&] { return bus.status() && bus.status()->state == "matching"; }))
      << process.Output();
  for (const auto& frame : frames) {
    Flood(bus, both);
    bus.Publish(ch::kStereoImages, AsSent(ch::kStereoImages, frame));
    // stereo-match holds two messages while it matches; wait for the disparity.
    const size_t expected = size_t(frame.frame_id + 1);
    bus.ListenUntil(20, [&] { return bus.Payloads(ch::kStereoDisparity).size() >= expected; });
  }
  const int good = int(frames.size());
  const bool settled = bus.ListenUntil(30, [&] {
    const auto images = bus.Counters(ch::kStereoImages);
    const auto calibrations = bus.Counters(ch::kStereoCalibration);
    return images.received > 0 && images.received == good + images.rejected &&
           calibrations.received == 1 + calibrations.rejected &&
           bus.Counters(ch::kStereoDisparity).published == good;
  });
  process.Signal(SIGINT);
  const auto r = process.Wait(20);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(settled) << "the counters never accounted for everything sent";
  EXPECT_EQ(bus.Payloads(ch::kStereoDisparity), clean);
  ExpectRejectedAllBad(bus, bad_calibrations, 1);
  ExpectRejectedAllBad(bus, bad_frames, good);
}

}  // namespace
