#include <gtest/gtest.h>

#include <thread>
#include <vector>

#include "runtime/stage_times.h"

namespace {

TEST(StageTimes, MedianAndP99OverTheLastFramesOfEachStage) {
  ws::StageTimes times;
  for (int i = 1; i <= 100; ++i) times.Add("match", i);
  times.Add("cloud", 2.5);
  const auto summary = times.Summary();
  ASSERT_EQ(summary.size(), 2u);
  EXPECT_EQ(summary[0].stage, "match");  // in the order first timed
  EXPECT_EQ(summary[0].count, 100);
  EXPECT_EQ(summary[0].window, 100);
  EXPECT_FLOAT_EQ(summary[0].median_ms, 51);
  EXPECT_FLOAT_EQ(summary[0].p99_ms, 100);
  EXPECT_EQ(summary[1].stage, "cloud");
  EXPECT_FLOAT_EQ(summary[1].median_ms, 2.5f);
}

TEST(StageTimes, OldFramesLeaveTheWindow) {
  ws::StageTimes times;
  for (int i = 0; i < ws::StageTimes::kWindow; ++i) times.Add("match", 1000);
  for (int i = 0; i < ws::StageTimes::kWindow; ++i) times.Add("match", 5);
  const auto summary = times.Summary();
  EXPECT_EQ(summary[0].count, 2 * ws::StageTimes::kWindow);
  EXPECT_EQ(summary[0].window, ws::StageTimes::kWindow);
  EXPECT_FLOAT_EQ(summary[0].p99_ms, 5);
}

TEST(StageTimes, TimersOnSeveralThreadsAllCount) {
  ws::StageTimes times;
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&] {
      for (int i = 0; i < 500; ++i) ws::StageTimer timer(times, "stage");
    });
  for (auto& thread : threads) thread.join();
  const auto summary = times.Summary();
  ASSERT_EQ(summary.size(), 1u);
  EXPECT_EQ(summary[0].count, 2000);
  EXPECT_GE(summary[0].median_ms, 0);
  EXPECT_LE(summary[0].median_ms, summary[0].p99_ms);
}

// The CPU part holds the CPU time the process spent while the stage ran:
// here at least the 20 ms of it the stage burns on its own thread, whatever
// the wall time (nothing is asserted of that).
TEST(StageTimes, WithCpuTheStageAlsoReportsTheProcesssCpuTimeAsAPart) {
  ws::StageTimes times;
  constexpr double kBurnMs = 20;
  {
    ws::StageTimer timer(times, "filter", ws::StageTimer::Cpu::process);
    const double start = ws::ProcessCpuMs();
    volatile double sink = 0;
    while (ws::ProcessCpuMs() - start < kBurnMs) sink = sink + 1;
  }
  { ws::StageTimer timer(times, "publish"); }
  const auto summary = times.Summary();
  ASSERT_EQ(summary.size(), 3u);
  EXPECT_EQ(summary[0].stage, "filter");
  EXPECT_EQ(summary[1].stage, "filter: CPU");
  EXPECT_TRUE(ws::IsStagePart(summary[1].stage));
  EXPECT_EQ(summary[1].count, 1);
  EXPECT_GE(summary[1].median_ms, kBurnMs);
  EXPECT_EQ(summary[2].stage, "publish");  // no CPU part without Cpu::process
}

TEST(StageTimes, APartIsNamedAfterItsStageAndToldApart) {
  EXPECT_EQ(ws::StagePart("filter", "voxel"), "filter: voxel");
  EXPECT_TRUE(ws::IsStagePart(ws::StagePart("filter", "voxel")));
  EXPECT_FALSE(ws::IsStagePart("filter"));
  EXPECT_FALSE(ws::IsStagePart("publish STEREO_CLOUD_FILTERED"));
}

}  // namespace
