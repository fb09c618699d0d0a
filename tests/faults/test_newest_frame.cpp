// A publisher at 30 Hz into stereo-match, over real udpm, faster than it
// matches (full SGBM on 1280x960 pairs): it works on the newest pair waiting,
// never on a backlog. The frame it takes for matching is never more than 2
// behind the newest one sent at that moment, and every frame sent from the
// first one it received on is published, or counted as skipped (replaced by a
// newer one) or dropped (lost).
//
// When it takes frame k, the output of frame k - 1 has not arrived yet (it is
// still being published, or matching waits for its publishing to start), so
// the newest frame sent when output k - 1 arrives bounds the newest sent when
// frame k was taken: the test checks the bound against that, a stricter test.
// A handler that works through LCM's queue lags by a whole matching time
// (6 or more frames at 30 Hz).
#include <gtest/gtest.h>
#include <signal.h>

#include <algorithm>
#include <cstdio>

#include <opencv2/core.hpp>

#include "bus_watch.h"
#include "lcm_io/channels.h"
#include "lcm_io/image_codec.h"
#include "match_fixtures.h"
#include "test_support.h"
#include "widestereo/disparity_t.hpp"
#include "widestereo/stereo_frame_t.hpp"

namespace {

using namespace ws::test;
namespace ch = ws::channel;

// The sanitizers slow our own code several times over (the cloud stage most)
// and OpenCV's not at all, so the stages' shares of a frame's time change:
// the lag seen at the output and the outputs during the burst say nothing in
// make test-asan. Like the memory bounds (test_support.h), they are checked
// in the normal build only; the accounting is checked in both.
constexpr bool kTimingMeaningful = kMemoryBoundsMeaningful;

struct Output {
  int64_t frame_id;
  int newest_sent;  // the newest frame id sent when it arrived
  bool in_burst;
};

TEST(NewestFrame, StereoMatchAt30HzWorksOnTheNewestFrameAndCountsEveryOther) {
  const std::string dir = TempDir("faults-newest");
  const std::string url = UniqueUdpmUrl(17) + "&recv_buf_size=16777216";
  Command process({"stereo-match", "--log-dir", dir, "--in-url", url, "--out-url", url,
                   "--matcher", "sgbm", "--num-disparities", "128", "--cloud-step", "8"});
  BusWatch bus(url, "stereo-match");
  bus.Collect(ch::kStereoDisparity);
  ASSERT_TRUE(StartMatching(bus, IdentityCalibration(1280, 960, 1000, 0.1))) << process.Output();

  cv::Mat texture(960, 1280, CV_8UC1);
  cv::randu(texture, 0, 256);
  widestereo::stereo_frame_t frame{};
  frame.left = frame.right = ws::MatToImage(texture, 0);
  int next_id = 0;
  bool in_burst = false;
  std::vector<Output> outputs;
  auto send = [&] {
    frame.frame_id = next_id++;
    frame.utime = frame.left.utime = frame.right.utime = next_id * 33333;
    bus.Publish(ch::kStereoImages, frame);
  };
  // Keeps the frame ids of the disparities as they arrive (not the payloads).
  auto note_outputs = [&] {
    for (const auto& bytes : bus.TakePayloads(ch::kStereoDisparity)) {
      widestereo::disparity_t d;
      if (d.decode(bytes.data(), 0, int(bytes.size())) > 0) outputs.push_back({d.frame_id, next_id - 1, in_burst});
    }
    return false;
  };
  bool first_received = false;
  for (int attempt = 0; attempt < 5 && !first_received; ++attempt) {
    send();
    first_received = bus.ListenUntil(10, [&] {
      note_outputs();
      return bus.Counters(ch::kStereoImages).received == 1;
    });
  }
  ASSERT_TRUE(first_received) << process.Output();
  const int first_id = next_id - 1;
  bus.ListenUntil(10, [&] { note_outputs(); return !outputs.empty(); });
  outputs.clear();
  constexpr int kFrames = 240;  // 8 s at 30 Hz
  in_burst = true;
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < kFrames; ++i) {
    send();
    const auto next = start + std::chrono::microseconds(33333 * (i + 1));
    const double left = std::chrono::duration<double>(next - std::chrono::steady_clock::now()).count();
    bus.ListenUntil(std::max(left, 0.0), note_outputs);
  }
  in_burst = false;
  // Closing frames, one at a time, until every frame is accounted for: the
  // last one received closes the gap of any lost before it.
  auto accounted = [&] {
    note_outputs();
    const auto c = bus.Counters(ch::kStereoImages);
    return bus.Counters(ch::kStereoDisparity).published + c.dropped + c.skipped + c.rejected == next_id - first_id;
  };
  bool all_accounted = false;
  for (int attempt = 0; attempt < 6 && !all_accounted; ++attempt) {
    send();
    all_accounted = bus.ListenUntil(10, accounted);
  }
  process.Signal(SIGINT);
  const auto r = process.Wait(20);
  EXPECT_EQ(r.exit_code, 0) << r.output;

  const auto in = bus.Counters(ch::kStereoImages);
  const auto out = bus.Counters(ch::kStereoDisparity);
  int burst_outputs = 0, worst_lag = 0;
  for (size_t k = 1; k < outputs.size(); ++k) {
    if (!outputs[k].in_burst || !outputs[k - 1].in_burst) continue;
    burst_outputs++;
    const int lag = outputs[k - 1].newest_sent - int(outputs[k].frame_id);
    worst_lag = std::max(worst_lag, lag);
    if (kTimingMeaningful) {
      EXPECT_LE(lag, 2) << "frame " << outputs[k].frame_id << " taken when " << outputs[k - 1].newest_sent
                        << " had been sent";
    }
  }
  std::printf("newest frame: %d pairs sent at 30 Hz, %ld matched, %ld skipped, %ld dropped; worst lag %d frames "
              "over %d outputs\n",
              next_id - first_id, long(out.published), long(in.skipped), long(in.dropped), worst_lag, burst_outputs);
  EXPECT_TRUE(all_accounted) << "frames neither matched nor counted as skipped or dropped: " << out.published
                             << " + " << in.skipped << " + " << in.dropped << " + " << in.rejected << " of "
                             << next_id - first_id;
  EXPECT_EQ(in.rejected, 0);
  EXPECT_GT(in.skipped, 0);     // it could not keep up: it skipped
  if (kTimingMeaningful) {
    EXPECT_GE(burst_outputs, 3);  // and it matched all along (a loaded machine matches slowly)
  }
}

}  // namespace
