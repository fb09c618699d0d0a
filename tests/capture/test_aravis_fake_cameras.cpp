// Fake GigE Vision cameras on this host serve known frames over real GVCP and
// GVSP; AravisCamera and AravisStereoPair read them back.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <functional>
#include <future>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "capture/aravis_camera.h"
#include "capture/aravis_stereo_pair.h"
#include "capture/camera_error.h"
#include "fake_cameras/fake_gige_camera.h"
#include "fake_cameras/fake_stereo_cameras.h"
#include "capture/gige_address.h"
#include "lcm_io/channels.h"
#include "lcm_io/image_codec.h"
#include "test_support.h"
#include "widestereo/stereo_frame_t.hpp"

namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

const cv::Size kSize{1280, 960};
constexpr uint8_t kLeftShade = 60;
constexpr uint8_t kRightShade = 180;

double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Frame `index` of a side: one shade per side, the index in the first 8 pixels.
cv::Mat IndexedFrame(int64_t index, bool left) {
  cv::Mat image(kSize, CV_8UC1, cv::Scalar(left ? kLeftShade : kRightShade));
  std::memcpy(image.ptr(0), &index, sizeof index);
  return image;
}

int64_t IndexOf(const cv::Mat& image) {
  int64_t index = 0;
  std::memcpy(&index, image.ptr(0), sizeof index);
  return index;
}

// Unique per test process: fake cameras of tests running at once must not be confused.
std::string Serial(const char* side) { return side + std::to_string(getpid()); }

// As config/rig/fake-gige.yaml: pairs by the fake cameras' clock with the
// tolerance FakeStereoCameras calls one moment.
ws::ArvCameraSettings Settings(ws::TriggerMode trigger) {
  ws::ArvCameraSettings settings;
  settings.frame_rate_hz = 10;
  settings.pairing_tolerance_ms = ws::FakeStereoCamerasConfig().same_moment_ms;
  settings.pairing_clock = ws::PairingClock::camera;
  settings.packet_size = 8192;
  settings.trigger = trigger;
  return settings;
}

ws::AravisCameraOptions QuickToNotice() {
  ws::AravisCameraOptions options;
  options.stall_timeout = 300ms;
  options.retry_interval = 200ms;
  return options;
}

class FakeCameras : public ::testing::Test {
 protected:
  void SetUp() override {
    addresses_ = ws::LocalIpv4Addresses();
    if (addresses_.size() < 2)
      GTEST_SKIP() << "two fake GigE Vision cameras need two IPv4 addresses of this host; add "
                      "one: ip addr add 127.0.0.2/8 dev lo";
  }

  std::unique_ptr<ws::FakeStereoCameras> ServeRig() {
    ws::FakeStereoCamerasConfig config;
    config.left_address = addresses_[0];
    config.right_address = addresses_[1];
    config.left_serial = Serial("L");
    config.right_serial = Serial("R");
    return std::make_unique<ws::FakeStereoCameras>(config, IndexedFrame);
  }

  // Pairs in step (same simulated moment on both sides, each side's own image).
  static void ExpectInStep(const ws::StereoFrame& pair) {
    ASSERT_EQ(pair.left.image.size(), kSize);
    ASSERT_EQ(pair.left.image.type(), CV_8UC1);
    EXPECT_EQ(IndexOf(pair.left.image), IndexOf(pair.right.image));
    EXPECT_EQ(pair.left.image.at<uint8_t>(kSize.height - 1, 0), kLeftShade);
    EXPECT_EQ(pair.right.image.at<uint8_t>(kSize.height - 1, 0), kRightShade);
  }

  std::vector<std::string> addresses_;
};

TEST_F(FakeCameras, OneCameraServesEachPixelFormatAsSet) {
  const cv::Mat gray_ramp = [] {
    cv::Mat ramp(48, 64, CV_8UC1);
    for (int y = 0; y < ramp.rows; ++y)
      for (int x = 0; x < ramp.cols; ++x) ramp.at<uint8_t>(y, x) = uint8_t(x * 4 + y);
    return ramp;
  }();
  ws::FakeGigeCameraConfig config;
  config.address = addresses_[0];
  config.serial = Serial("S");
  config.size = gray_ramp.size();
  ws::FakeGigeCamera fake(config,
                          [&](const ws::FakeGigeCamera::FrameRequest&) { return gray_ramp; });

  for (const char* format : {"Mono8", "Mono16", "RGB8"}) {
    SCOPED_TRACE(format);
    ws::ArvCameraSettings settings = Settings(ws::TriggerMode::software);
    settings.pixel_format = format;
    ws::AravisCamera camera(config.address, settings);  // opened by address, not discovery
    ASSERT_TRUE(camera.WaitConnected(5s)) << camera.last_error();
    ws::GrabResult result;
    for (int attempt = 0; attempt < 5 && result.status != ws::GrabStatus::frame; ++attempt) {
      camera.RequestTrigger();  // the first frame of a connection is dropped
      result = camera.Grab(1s);
    }
    ASSERT_EQ(result.status, ws::GrabStatus::frame);
    const cv::Mat& image = result.frame.image;
    ASSERT_EQ(image.size(), gray_ramp.size());
    if (std::string(format) == "Mono8") {
      EXPECT_EQ(cv::norm(image, gray_ramp, cv::NORM_INF), 0);
    } else if (std::string(format) == "Mono16") {
      ASSERT_EQ(image.type(), CV_16UC1);
      EXPECT_EQ(image.at<uint16_t>(3, 5), gray_ramp.at<uint8_t>(3, 5) * 257);
    } else {
      ASSERT_EQ(image.type(), CV_8UC3);
      EXPECT_EQ(image.at<cv::Vec3b>(3, 5), cv::Vec3b::all(gray_ramp.at<uint8_t>(3, 5)));
    }
    EXPECT_GT(result.frame.host_timestamp_ns, 0);
    bool warned_about_gain = false;
    for (const std::string& event : camera.TakeEvents())
      warned_about_gain |= event.find("no Gain (dB) feature") != std::string::npos;
    EXPECT_TRUE(warned_about_gain) << "the fake camera has GainRaw only";
  }
  EXPECT_TRUE(fake.last_error().empty()) << fake.last_error();
}

TEST_F(FakeCameras, SoftwareTriggerGivesPairsInStepAndInOrder) {
  auto rig = ServeRig();
  ws::AravisStereoPair pair(rig->camera(ws::Side::left).device_id(),
                            rig->camera(ws::Side::right).device_id(),
                            Settings(ws::TriggerMode::software));
  constexpr int kPairs = 12;
  int64_t previous = -1;
  Clock::time_point first_pair;
  for (int i = 0; i < kPairs; ++i) {
    const auto stereo = pair.Next(5s);
    ASSERT_TRUE(stereo) << "pair " << i << ": " << pair.last_error();
    if (i == 0) first_pair = Clock::now();
    ExpectInStep(*stereo);
    const int64_t index = IndexOf(stereo->left.image);
    EXPECT_GT(index, previous);
    previous = index;
  }
  std::printf("software trigger: %.1f pairs/s of 1280x960 Mono8 (asked 10)\n",
              (kPairs - 1) / SecondsSince(first_pair));
  const ws::StereoPairCounters counters = pair.counters();
  EXPECT_EQ(counters.pairs, uint64_t(kPairs));
  EXPECT_EQ(counters.left.reconnects + counters.right.reconnects, 0u);
}

TEST_F(FakeCameras, FreeRunPairsByTimestamp) {
  auto rig = ServeRig();
  const ws::ArvCameraSettings settings = Settings(ws::TriggerMode::free_run);
  ws::AravisStereoPair pair(rig->camera(ws::Side::left).device_id(),
                            rig->camera(ws::Side::right).device_id(), settings);
  int64_t previous = -1;
  for (int i = 0; i < 10; ++i) {
    const auto stereo = pair.Next(5s);
    ASSERT_TRUE(stereo) << "pair " << i << ": " << pair.last_error();
    ExpectInStep(*stereo);
    EXPECT_GT(IndexOf(stereo->left.image), previous);
    previous = IndexOf(stereo->left.image);
    EXPECT_LE(std::llabs(stereo->left.camera_timestamp_ns - stereo->right.camera_timestamp_ns),
              settings.pairing_tolerance_ms * 1e6);
  }
}

// Takes pairs until one arrives from the reconnected right camera; returns
// the seconds it took.
double SecondsToPairAfterReconnect(ws::AravisStereoPair& pair, std::chrono::seconds limit) {
  const auto start = Clock::now();
  while (Clock::now() - start < limit)
    if (pair.Next(200ms) && pair.counters().right.reconnects > 0) return SecondsSince(start);
  ADD_FAILURE() << "no pair within " << limit.count() << " s: " << pair.last_error();
  return -1;
}

TEST_F(FakeCameras, PairRecoversWhenACameraIsUnpluggedAndComesBack) {
  auto rig = ServeRig();
  ws::FakeGigeCamera& right = rig->camera(ws::Side::right);
  ws::AravisStereoPair pair(rig->camera(ws::Side::left).device_id(), right.device_id(),
                            Settings(ws::TriggerMode::software), QuickToNotice());
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(pair.Next(5s)) << pair.last_error();

  right.Stop();
  const auto unplugged = Clock::now();
  while (pair.connected() && SecondsSince(unplugged) < 10) pair.Next(100ms);
  ASSERT_FALSE(pair.connected()) << "the loss went unnoticed";
  const double noticed_s = SecondsSince(unplugged);

  right.Start();
  const double recovered_s = SecondsToPairAfterReconnect(pair, 10s);
  std::printf("unplugged: noticed after %.2f s; back in step %.2f s after the camera returned\n",
              noticed_s, recovered_s);
  for (int i = 0; i < 3; ++i) {
    const auto stereo = pair.Next(5s);
    ASSERT_TRUE(stereo) << pair.last_error();
    ExpectInStep(*stereo);
  }
  const ws::StereoPairCounters counters = pair.counters();
  EXPECT_EQ(counters.right.reconnects, 1u);
  EXPECT_EQ(counters.left.reconnects, 0u);
  EXPECT_GT(counters.right.timeouts, 0u);
  EXPECT_GT(counters.unpaired_left, 0u) << "left frames of the outage have no partner";
  EXPECT_NE(pair.last_error().find("right: "), std::string::npos) << pair.last_error();
}

TEST_F(FakeCameras, PairRecoversWhenACameraRestarts) {
  auto rig = ServeRig();
  ws::FakeGigeCamera& right = rig->camera(ws::Side::right);
  ws::AravisStereoPair pair(rig->camera(ws::Side::left).device_id(), right.device_id(),
                            Settings(ws::TriggerMode::software), QuickToNotice());
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(pair.Next(5s)) << pair.last_error();

  right.Stop();  // a power cycle: back at once, with no controller and not acquiring
  right.Start();
  const double recovered_s = SecondsToPairAfterReconnect(pair, 10s);
  std::printf("restarted: back in step after %.2f s\n", recovered_s);
  const auto stereo = pair.Next(5s);
  ASSERT_TRUE(stereo) << pair.last_error();
  ExpectInStep(*stereo);
  EXPECT_EQ(pair.counters().right.reconnects, 1u);
  bool told = false;
  for (const std::string& event : pair.TakeEvents()) told |= event.rfind("right lost", 0) == 0;
  EXPECT_TRUE(told);
}

TEST_F(FakeCameras, AnAddressServesOneCameraAtATime) {
  const auto black = [](const ws::FakeGigeCamera::FrameRequest&) { return cv::Mat(); };
  ws::FakeGigeCameraConfig config;
  config.address = addresses_[0];
  config.serial = Serial("A");
  {
    ws::FakeGigeCamera first(config, black);
    EXPECT_FALSE(ws::GvcpAddressFree(config.address)) << "stereo-fake-cameras' auto passes it over";
    config.serial = Serial("B");
    config.address_wait = 100ms;
    std::vector<std::string> told;
    config.waiting = [&told](const std::string& what) { told.push_back(what); };
    try {
      ws::FakeGigeCamera second(config, black);
      ADD_FAILURE() << "two cameras at " << config.address;
    } catch (const ws::CameraError& e) {
      EXPECT_NE(std::string(e.what()).find("another fake camera serves at"), std::string::npos)
          << e.what();
    }
    ASSERT_EQ(told.size(), 1u) << "it says once what it waits for";
    EXPECT_NE(told[0].find("waiting up to 0.1 s for " + config.address + ": another fake camera serves there"),
              std::string::npos)
        << told[0];
  }
  EXPECT_TRUE(ws::GvcpAddressFree(config.address)) << "free again once the camera has gone";
  config.waiting = nullptr;
  config.address = "192.0.2.254";  // TEST-NET-1, not ours
  EXPECT_THROW(ws::FakeGigeCamera(config, black), ws::CameraError);
}

TEST_F(FakeCameras, StereoFakeCamerasProcessServesARig) {
  const std::string left = Serial("PL");
  const std::string right = Serial("PR");
  auto server = std::async(std::launch::async, [&] {
    return ws::test::RunCommand({"stereo-fake-cameras", "--duration", "3", "--left-serial", left,
                                 "--right-serial", right, "--out-url", ws::test::UniqueUdpmUrl(),
                                 "--log-dir", ws::test::TempDir("fake_cameras_logs")},
                                60);
  });
  {  // closed before the server goes: closing a camera that has gone takes seconds
    ws::AravisStereoPair pair("Aravis-Fake-" + left, "Aravis-Fake-" + right,
                              Settings(ws::TriggerMode::software));
    for (int i = 0; i < 5; ++i) {
      // The server may first wait for fake cameras of tests running at the same time.
      const auto stereo = pair.Next(i == 0 ? 40s : 5s);
      ASSERT_TRUE(stereo) << pair.last_error();
      EXPECT_EQ(stereo->left.image.size(), kSize);  // the pattern's default size
      EXPECT_GT(cv::norm(stereo->left.image, stereo->right.image, cv::NORM_INF), 0);
    }
  }
  const ws::test::CommandResult result = server.get();
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("--source aravis:Aravis-Fake-" + left + ",Aravis-Fake-" + right),
            std::string::npos)
      << result.output;
}

// stereo-capture --source aravis:... over the fake rig, to a log; returns the
// process's result. `during` runs while the capture does.
ws::test::CommandResult CaptureFromRig(ws::FakeStereoCameras& rig, const std::string& log, int count,
                                       const std::function<void()>& during = [] {}) {
  auto capture = std::async(std::launch::async, [&] {
    return ws::test::RunCommand(
        {"stereo-capture", "--source",
         "aravis:" + rig.camera(ws::Side::left).device_id() + "," + rig.camera(ws::Side::right).device_id(),
         "--rig", ws::test::SourceDir() + "/config/rig/fake-gige.yaml", "--count", std::to_string(count),
         "--out-url", "file://" + log + "?mode=w", "--log-dir", ws::test::TempDir("aravis_capture_logs")},
        60);
  });
  during();
  return capture.get();
}

// The pairs on STEREO_IMAGES: every frame id once, in order, each pair in step.
std::vector<widestereo::stereo_frame_t> ExpectPairsInStep(const std::string& log, int count) {
  const auto frames = ws::test::Messages<widestereo::stereo_frame_t>(ws::test::ReadLog(log), ws::channel::kStereoImages);
  EXPECT_EQ(frames.size(), size_t(count));
  for (size_t i = 0; i < frames.size(); ++i) {
    EXPECT_EQ(frames[i].frame_id, int64_t(i));
    const cv::Mat left = ws::ImageToMat(frames[i].left);
    const cv::Mat right = ws::ImageToMat(frames[i].right);
    EXPECT_EQ(left.size(), kSize);
    EXPECT_EQ(IndexOf(left), IndexOf(right)) << "frame " << i << " mixes two moments";
    EXPECT_EQ(left.at<uint8_t>(kSize.height - 1, 0), kLeftShade);
    EXPECT_EQ(right.at<uint8_t>(kSize.height - 1, 0), kRightShade);
  }
  return frames;
}

TEST_F(FakeCameras, StereoCapturePublishesTheCamerasPairsInStep) {
  auto rig = ServeRig();
  const std::string log = ws::test::TempDir("aravis_capture") + "/out.lcmlog";
  const ws::test::CommandResult result = CaptureFromRig(*rig, log, 10);
  ASSERT_EQ(result.exit_code, 0) << result.output;
  ExpectPairsInStep(log, 10);
  const auto left = ws::test::LastCounters(log, "stereo-capture", "aravis:" + rig->camera(ws::Side::left).device_id());
  EXPECT_GE(left.received, 10);
  // Whole frames but for the odd one whose packets a starved machine did not
  // receive in time on loopback: counted as rejected, never published (every
  // pair above is whole and in step).
  EXPECT_LT(left.rejected, left.received);
}

TEST_F(FakeCameras, StereoCaptureRecoversWhenACameraRestartsAndCountsTheGap) {
  auto rig = ServeRig();
  ws::FakeGigeCamera& left = rig->camera(ws::Side::left);
  ws::FakeGigeCamera& right = rig->camera(ws::Side::right);
  // The right camera is off while the left one serves 15 frames (1.5 s at 10 Hz).
  constexpr uint64_t kOutageFrames = 15;
  const std::string log = ws::test::TempDir("aravis_capture_restart") + "/out.lcmlog";
  const ws::test::CommandResult result = CaptureFromRig(*rig, log, 25, [&] {
    const auto start = Clock::now();
    while (right.frames_served() < 5 && SecondsSince(start) < 30) std::this_thread::sleep_for(20ms);
    right.Stop();
    const uint64_t stopped_at = left.frames_served();
    while (left.frames_served() < stopped_at + kOutageFrames && SecondsSince(start) < 30)
      std::this_thread::sleep_for(20ms);
    right.Start();
  });
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const auto frames = ExpectPairsInStep(log, 25);
  ASSERT_EQ(frames.size(), 25u);
  EXPECT_GT(frames.back().utime - frames.front().utime, int64_t((kOutageFrames - 1) * 1e5 + 23 * 1e5 * 0.9))
      << "the outage must lie between the first and the last pair";
  const auto counters = ws::test::LastCounters(log, "stereo-capture", "aravis:" + left.device_id());
  EXPECT_GT(counters.dropped, 0) << "left frames of the outage had no partner and must be counted";
}

TEST(StereoFakeCamerasProcess, AnswersHelp) {
  const ws::test::CommandResult result =
      ws::test::RunCommand({"stereo-fake-cameras", "--help"}, 20);
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_NE(result.output.find("--frames"), std::string::npos) << result.output;
}

TEST(AravisCameraIds, ParsesTwoIds) {
  EXPECT_EQ(ws::ParseAravisCameraIds("Aravis-Fake-L, 10.0.0.7"),
            (std::pair<std::string, std::string>{"Aravis-Fake-L", "10.0.0.7"}));
  EXPECT_THROW(ws::ParseAravisCameraIds("only-one"), std::invalid_argument);
  EXPECT_THROW(ws::ParseAravisCameraIds("a,b,c"), std::invalid_argument);
  EXPECT_THROW(ws::ParseAravisCameraIds(",b"), std::invalid_argument);
}

}  // namespace
