// stereo-match's --latency-budget over real udpm: a pair too old for the
// budget is skipped whole before it is matched (no disparity, no cloud of
// it), counted as skipped with its reason, and the pairs about it go
// through. The ages come from the pairs' stamps on this host's clock, set
// here: a pair 5 s old against a 1 s budget, and fresh ones, so that no
// machine is slow enough to make a fresh one late.
#include <gtest/gtest.h>
#include <signal.h>

#include <set>

#include <opencv2/core.hpp>

#include "bus_watch.h"
#include "lcm_io/channels.h"
#include "lcm_io/image_codec.h"
#include "match_fixtures.h"
#include "runtime/latency_budget.h"
#include "runtime/wall_clock.h"
#include "test_support.h"
#include "widestereo/disparity_t.hpp"
#include "widestereo/point_cloud_t.hpp"
#include "widestereo/stereo_frame_t.hpp"

namespace {

using namespace ws::test;
namespace ch = ws::channel;

constexpr int64_t kOld = 5'000'000;  // microseconds: 5 s, against a budget of 1 s
const std::string kBudgetMs = "1000";

// The frame ids of the messages of type Msg kept on `channel`.
template <class Msg>
std::set<int64_t> FrameIds(BusWatch& bus, const std::string& channel) {
  std::set<int64_t> ids;
  for (const auto& bytes : bus.Payloads(channel)) {
    Msg msg;
    if (msg.decode(bytes.data(), 0, int(bytes.size())) > 0) ids.insert(msg.frame_id);
  }
  return ids;
}

// True once the watched process's heartbeat counts at least `skipped`
// skipped on `channel`.
bool SkippedCounted(BusWatch& bus, const std::string& channel, int64_t skipped) {
  return bus.ListenUntil(10, [&] { return bus.Counters(channel).skipped >= skipped; });
}

TEST(LatencyBudget, StereoMatchSkipsAPairTooOldForItsBudgetWholeBeforeMatchingIt) {
  const std::string dir = TempDir("faults-budget-match");
  const std::string url = UniqueUdpmUrl(23) + "&recv_buf_size=16777216";
  Command process({"stereo-match", "--log-dir", dir, "--in-url", url, "--out-url", url, "--num-disparities", "16",
                   "--latency-budget", kBudgetMs});
  BusWatch bus(url, "stereo-match");
  bus.Collect(ch::kStereoDisparity);
  bus.Collect(ch::kStereoCloud);
  ASSERT_TRUE(StartMatching(bus, IdentityCalibration(320, 240, 250, 0.1))) << process.Output();

  cv::Mat texture(240, 320, CV_8UC1);
  cv::randu(texture, 0, 256);
  int64_t id = 0;
  auto send = [&](int64_t age_us) {
    widestereo::stereo_frame_t frame{};
    frame.frame_id = ++id;
    frame.utime = ws::WallMicros() - age_us;
    frame.left = frame.right = ws::MatToImage(texture, frame.utime);
    bus.Publish(ch::kStereoImages, frame);
  };
  auto matched = [&](int64_t frame_id) {
    return bus.ListenUntil(10, [&] { return FrameIds<widestereo::disparity_t>(bus, ch::kStereoDisparity).count(frame_id) > 0; });
  };
  // Fresh pairs until one is matched (the first may come while the maps are built).
  bool started = false;
  for (int attempt = 0; attempt < 5 && !started; ++attempt) {
    send(0);
    started = matched(id);
  }
  ASSERT_TRUE(started) << process.Output();
  // Every pair so far matched or skipped (for the maps), as its heartbeat says.
  auto accounted = [&] {
    return bus.Counters(ch::kStereoDisparity).published + bus.Counters(ch::kStereoImages).skipped == id;
  };
  ASSERT_TRUE(bus.ListenUntil(10, accounted));
  const int64_t skipped_before = bus.Counters(ch::kStereoImages).skipped;

  send(kOld);
  const int64_t old_id = id;
  ASSERT_TRUE(SkippedCounted(bus, ch::kStereoImages, skipped_before + 1)) << process.Output();
  send(0);
  ASSERT_TRUE(matched(id)) << "the fresh pair after the old one; " << ReadFileText(dir + "/stereo-match.log");
  ASSERT_TRUE(bus.ListenUntil(10, [&] { return FrameIds<widestereo::point_cloud_t>(bus, ch::kStereoCloud).count(id) > 0; }));
  process.Signal(SIGINT);
  EXPECT_EQ(process.Wait(20).exit_code, 0);

  EXPECT_EQ(FrameIds<widestereo::disparity_t>(bus, ch::kStereoDisparity).count(old_id), 0u) << "no disparity of it";
  EXPECT_EQ(FrameIds<widestereo::point_cloud_t>(bus, ch::kStereoCloud).count(old_id), 0u) << "no cloud of it";
  const std::string log = ReadFileText(dir + "/stereo-match.log");
  EXPECT_NE(log.find(std::string(ws::LatencyBudget::kSkipReason) + " 1"), std::string::npos) << log;
}

}  // namespace
