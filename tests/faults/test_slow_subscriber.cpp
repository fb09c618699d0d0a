// A subscriber slower than its publisher, over real udpm: stereo-match gets
// 1280x960 pairs faster than it matches them. It keeps only the newest one
// waiting; the ones it replaces are counted as skipped, and any LCM lost
// as dropped (frame-id gaps), in PROCESS_STATUS, so that every frame sent from the
// first one it received on is either matched or counted as skipped or dropped. (Frames lost before the first one
// it receives cannot be known to it: the test first sends single frames until
// one arrives, then the burst.) Its memory grows by its working buffers, not
// with what was sent.
// (stereo-detect's own queue is tested in tests/detect.)
#include <gtest/gtest.h>
#include <signal.h>

#include <opencv2/core.hpp>

#include "bus_watch.h"
#include "lcm_io/channels.h"
#include "lcm_io/image_codec.h"
#include "match_fixtures.h"
#include "test_support.h"
#include "widestereo/stereo_frame_t.hpp"

namespace {

using namespace ws::test;
namespace ch = ws::channel;

TEST(SlowSubscriber, StereoMatchDropsAndCountsWhatItCannotKeepUpWith) {
  const std::string dir = TempDir("faults-slow");
  const std::string url = UniqueUdpmUrl(13) + "&recv_buf_size=8388608";
  Command process({"stereo-match", "--log-dir", dir, "--in-url", url, "--out-url", url,
                   "--num-disparities", "128"});
  BusWatch bus(url, "stereo-match");
  bus.Collect(ch::kStereoDisparity);
  ASSERT_TRUE(StartMatching(bus, IdentityCalibration(1280, 960, 1000, 0.1))) << process.Output();
  const int pid = bus.status()->pid;
  const long resident_before_kb = ResidentKb(pid, "VmRSS");

  cv::Mat texture(960, 1280, CV_8UC1);
  cv::randu(texture, 0, 256);
  widestereo::stereo_frame_t frame{};
  frame.left = frame.right = ws::MatToImage(texture, 0);  // 2.4 MB a pair
  int next_id = 0;
  auto send = [&] {
    frame.frame_id = next_id++;
    frame.utime = frame.left.utime = frame.right.utime = next_id * 33333;
    bus.Publish(ch::kStereoImages, frame);
  };
  bool first_received = false;
  for (int attempt = 0; attempt < 5 && !first_received; ++attempt) {
    send();
    first_received = bus.ListenUntil(10, [&] { return bus.Counters(ch::kStereoImages).received == 1; });
  }
  ASSERT_TRUE(first_received) << process.Output();
  const int first_id = next_id - 1;
  constexpr int kFrames = 60;  // 150 MB at 30 Hz
  for (int i = 0; i < kFrames; ++i) {
    send();
    bus.Listen(1.0 / 30);
  }
  // Closing frames, one at a time: the id of the first one it receives closes
  // the gap of the frames dropped before it. (A closing frame that comes
  // while LCM's queue is still full is dropped too; the next one counts it.)
  bool accounted = false;
  for (int attempt = 0; attempt < 6 && !accounted; ++attempt) {
    send();
    accounted = bus.ListenUntil(20, [&] {
      const auto c = bus.Counters(ch::kStereoImages);
      return bus.Counters(ch::kStereoDisparity).published + c.dropped + c.skipped + c.rejected ==
             next_id - first_id;
    });
  }
  const int sent = next_id - first_id;  // from the first one received on
  const long growth_kb = ResidentKb(pid, "VmHWM") - resident_before_kb;
  process.Signal(SIGINT);
  const auto r = process.Wait(20);
  EXPECT_EQ(r.exit_code, 0) << r.output;

  const auto in = bus.Counters(ch::kStereoImages);
  std::printf("slow subscriber: %d pairs sent, %ld matched, %ld skipped, %ld dropped; memory grew %ld MB\n",
              sent, long(bus.Counters(ch::kStereoDisparity).published), long(in.skipped), long(in.dropped),
              growth_kb / 1024);
  EXPECT_TRUE(accounted) << "frames neither matched nor counted as skipped or dropped";
  EXPECT_EQ(in.rejected, 0);
  EXPECT_GT(in.skipped, 0);  // it could not keep up
  EXPECT_EQ(bus.Counters(ch::kStereoDisparity).published + in.skipped + in.dropped, sent);
  if (kMemoryBoundsMeaningful) {
    EXPECT_LT(growth_kb, 100 * 1024);
  }
}

}  // namespace
