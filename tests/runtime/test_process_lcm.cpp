// Real processes over real LCM: replay of a file:// log to its end with bad
// messages rejected and counted, an empty and a damaged input log, two
// processes talking over udpm on this host, and a sampling subscriber's
// counts over udpm.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <thread>

#include "lcm_io/channels.h"
#include "lcm_io/image_codec.h"
#include "runtime/process.h"
#include "test_support.h"
#include "widestereo/process_status_t.hpp"
#include "widestereo/stereo_frame_t.hpp"

namespace {

using namespace ws::test;
using widestereo::process_status_t;

process_status_t Status(const std::string& name, int64_t utime) {
  process_status_t s{};
  s.utime = utime;
  s.name = name;
  s.host = "robot";
  s.pid = 1;
  s.nchannels = 0;
  return s;
}

// stereo-status from the log DIR/in.lcmlog to DIR/out.lcmlog.
CommandResult ReplayThroughStereoStatus(const std::string& dir) {
  return RunCommand({"stereo-status", "--log-dir", dir, "--in-url", "file://" + dir + "/in.lcmlog?speed=0",
                     "--out-url", "file://" + dir + "/out.lcmlog?mode=w"},
                    30);
}

TEST(ProcessLcm, ReplaysAFileLogToItsEndAndCountsRejections) {
  const std::string dir = TempDir("replay");
  std::vector<LogEvent> events;
  for (int i = 0; i < 5; ++i) events.push_back(Event("PROCESS_STATUS", Status("peer", 1000000 * i)));
  events.push_back({"PROCESS_STATUS", {1, 2, 3, 4, 5, 6, 7, 8, 9}, 0});  // garbage
  widestereo::stereo_frame_t frame{};
  events.push_back(Event("PROCESS_STATUS", frame));                        // wrong type
  auto truncated = Event("PROCESS_STATUS", Status("peer", 9));
  truncated.data.resize(truncated.data.size() - 2);
  events.push_back(truncated);
  WriteLog(dir + "/in.lcmlog", events);

  const auto r = ReplayThroughStereoStatus(dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("peer@robot"), std::string::npos) << r.output;
  const auto c = LastCounters(dir + "/out.lcmlog", "stereo-status", "PROCESS_STATUS");
  EXPECT_EQ(c.received, 8);
  EXPECT_EQ(c.rejected, 3);
}

// A subscription on a channel that carries every frame counts a frame-id
// gap as lost; one on a channel that carries only the frames its sender
// looked at counts it as skipped, with the reason; one that ignores gaps
// counts none.
TEST(ProcessLcm, FrameGapsAreLostSkippedOrIgnoredAsTheSubscriptionSays) {
  const std::string dir = TempDir("frame-gaps");
  std::vector<LogEvent> events;
  for (int64_t id : {1, 2, 5, 9})
    for (const char* channel : {"COUNTED", "SPARSE", "SOME_FRAMES"}) {
      widestereo::stereo_frame_t frame{};
      frame.frame_id = id;
      frame.utime = 1000000 * id;
      frame.left = frame.right = ws::MatToImage(cv::Mat(4, 4, CV_8U, cv::Scalar(7)), frame.utime);
      events.push_back(Event(channel, frame));
    }
  WriteLog(dir + "/in.lcmlog", events);
  ws::ProcessOptions options;
  options.name = "gaps";
  options.in_url = "file://" + dir + "/in.lcmlog?speed=0";
  options.out_url = "file://" + dir + "/out.lcmlog?mode=w";
  options.log_dir = dir;
  options.quiet = true;
  {
    ws::Process process(options);
    int handled = 0;
    using Gaps = ws::Process::FrameGaps;
    auto count = [&](widestereo::stereo_frame_t&) { ++handled; };
    process.Subscribe<widestereo::stereo_frame_t>("COUNTED", count);
    process.Subscribe<widestereo::stereo_frame_t>("SPARSE", count, 0, Gaps::skipped);
    process.Subscribe<widestereo::stereo_frame_t>("SOME_FRAMES", count, 0, Gaps::ignore);
    ASSERT_EQ(process.Run(), 0);
    EXPECT_EQ(handled, 12);
    EXPECT_EQ(process.Counters("COUNTED").dropped.load(), 5) << "3, 4, 6, 7 and 8";
    EXPECT_EQ(process.Counters("COUNTED").skipped.load(), 0);
    EXPECT_EQ(process.Counters("SPARSE").dropped.load(), 0);
    EXPECT_EQ(process.Counters("SPARSE").skipped.load(), 5) << "3, 4, 6, 7 and 8, passed over by the sender";
    EXPECT_EQ(process.Counters("SOME_FRAMES").dropped.load(), 0);
    EXPECT_EQ(process.Counters("SOME_FRAMES").skipped.load(), 0);
    EXPECT_EQ(process.Counters("SOME_FRAMES").received.load(), 4);
  }
  std::ifstream log(dir + "/gaps.log");  // the final line gives each skip's reason
  const std::string text((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find(std::string(ws::Process::kPassedOverUpstream) + " 5"), std::string::npos) << text;
}

TEST(ProcessLcm, EmptyInputLogEndsAtOnce) {
  const std::string dir = TempDir("empty");
  WriteLog(dir + "/in.lcmlog", {});
  const auto r = ReplayThroughStereoStatus(dir);
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

TEST(ProcessLcm, DamagedInputLogReplaysUpToTheCutAndSaysSo) {
  const std::string dir = TempDir("cut");
  std::vector<LogEvent> events;
  for (int i = 0; i < 4; ++i) events.push_back(Event("PROCESS_STATUS", Status("peer", 1000000 * i)));
  WriteLog(dir + "/in.lcmlog", events);
  std::filesystem::resize_file(dir + "/in.lcmlog", std::filesystem::file_size(dir + "/in.lcmlog") - 5);
  const auto r = ReplayThroughStereoStatus(dir);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("damaged"), std::string::npos) << r.output;
  EXPECT_EQ(LastCounters(dir + "/out.lcmlog", "stereo-status", "PROCESS_STATUS").received, 3);
}

// Garbage after the second of four events: LCM's reader alone would replay
// only the first (it checks for a sync word after each event).
TEST(ProcessLcm, LogDamagedInTheMiddleReplaysEveryCompleteEventBeforeIt) {
  const std::string dir = TempDir("middle");
  std::vector<LogEvent> events;
  for (int i = 0; i < 2; ++i) events.push_back(Event("PROCESS_STATUS", Status("peer", 1000000 * i)));
  WriteLog(dir + "/head.lcmlog", events);
  WriteLog(dir + "/tail.lcmlog", events);
  {
    std::ofstream in(dir + "/in.lcmlog", std::ios::binary);
    in << std::ifstream(dir + "/head.lcmlog", std::ios::binary).rdbuf() << "garbage"
       << std::ifstream(dir + "/tail.lcmlog", std::ios::binary).rdbuf();
  }
  const auto r = ReplayThroughStereoStatus(dir);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("bad sync word at byte"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("replaying the 2 complete events before it"), std::string::npos) << r.output;
  EXPECT_EQ(LastCounters(dir + "/out.lcmlog", "stereo-status", "PROCESS_STATUS").received, 2);
  for (const auto& entry : std::filesystem::directory_iterator(dir))  // the copy LCM read is gone
    EXPECT_EQ(entry.path().string().find("complete-events"), std::string::npos) << entry.path();
}

TEST(ProcessLcm, MissingInputLogIsAClearError) {
  const std::string dir = TempDir("missing");
  const auto r = RunCommand({"stereo-status", "--log-dir", dir, "--in-url",
                             "file://" + dir + "/nope.lcmlog?speed=0"}, 30);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("cannot open"), std::string::npos) << r.output;
}

TEST(ProcessLcm, TwoProcessesTalkOverUdpm) {
  const std::string dir = TempDir("udpm");
  const std::string bus = UniqueUdpmUrl();
  // The listener hears the talker's PROCESS_STATUS heartbeats over udpm and
  // records its own counters in a log.
  std::thread listener_thread;
  CommandResult listener;
  listener_thread = std::thread([&] {
    listener = RunCommand({"stereo-status", "--log-dir", dir, "--duration", "4", "--in-url", bus,
                           "--out-url", "file://" + dir + "/listener.lcmlog?mode=w"},
                          30);
  });
  const auto talker = RunCommand({"stereo-status", "--log-dir", dir + "/talker", "--duration", "3",
                                  "--in-url", UniqueUdpmUrl(1), "--out-url", bus},
                                 30);
  listener_thread.join();
  ASSERT_EQ(talker.exit_code, 0) << talker.output;
  ASSERT_EQ(listener.exit_code, 0) << listener.output;
  const auto c = LastCounters(dir + "/listener.lcmlog", "stereo-status", "PROCESS_STATUS");
  EXPECT_GE(c.received, 2);
  EXPECT_EQ(c.rejected, 0);
}

// A subscriber that samples (stereo-view): the frames it skips undecoded are
// counted as skipped, never as lost; a frame that really went missing is.
TEST(ProcessLcm, ASampledSubscriptionCountsSkipsApartFromLosses) {
  const std::string dir = TempDir("sampled");
  const ws::ProcessOptions options = LiveInFileOut("sampler", dir);
  ws::Process process(options);
  int calls = 0;
  std::vector<int64_t> handled;
  process.SubscribeSampled<widestereo::stereo_frame_t>(
      ws::channel::kStereoImages, [&] { return calls++ % 3 == 0; },
      [&](const widestereo::stereo_frame_t& frame) { handled.push_back(frame.frame_id); });
  std::thread run([&] { process.Run(); });

  lcm::LCM bus(options.in_url);
  widestereo::stereo_frame_t frame{};
  frame.left = ws::MatToImage(cv::Mat(4, 4, CV_8U, cv::Scalar(7)), 1);
  frame.right = frame.left;
  const ws::ChannelCounters& counters = process.Counters(ws::channel::kStereoImages);
  for (int64_t id : {1, 2, 3, 4, 5, 7, 8, 9}) {  // 6 lost on the way
    frame.frame_id = id;
    frame.utime = id;
    bus.publish(ws::channel::kStereoImages, &frame);
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (counters.received.load() < (id < 6 ? id : id - 1) && std::chrono::steady_clock::now() < until)
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  process.Stop();
  run.join();
  EXPECT_EQ(counters.received.load(), 8);
  EXPECT_EQ(handled, (std::vector<int64_t>{1, 4, 8}));
  EXPECT_EQ(counters.skipped.load(), 5);
  EXPECT_EQ(counters.dropped.load(), 1) << "frame 6, and only it";
  EXPECT_EQ(counters.rejected.load(), 0);
}

}  // namespace
