// LatencyBudget with the times given: which frames are late.
#include <gtest/gtest.h>

#include "runtime/latency_budget.h"
#include "runtime/recent_durations.h"

namespace {

using ws::LatencyBudget;
using std::chrono::milliseconds;

constexpr int64_t kNow = 1'800'000'000'000'000;  // microseconds of the wall clock

TEST(LatencyBudget, LateWhenTheAgePlusTheRestExceedsTheBudget) {
  const LatencyBudget budget(150);
  EXPECT_FALSE(budget.Late(kNow - 60'000, kNow, milliseconds(90))) << "60 + 90 ms: on the budget";
  EXPECT_TRUE(budget.Late(kNow - 61'000, kNow, milliseconds(90)));
  EXPECT_TRUE(budget.Late(kNow - 151'000, kNow, milliseconds(0)));
}

TEST(LatencyBudget, NoFrameIsLateWhenTheRestAloneTakesTheBudget) {
  const LatencyBudget budget(150);
  EXPECT_FALSE(budget.Late(kNow - 100'000, kNow, milliseconds(150)));
  EXPECT_FALSE(budget.Late(kNow - 100'000, kNow, milliseconds(200)));
  EXPECT_TRUE(budget.Late(kNow - 100'000, kNow, milliseconds(149)));
}

TEST(LatencyBudget, NoBoundAndStampsOfAnotherClockAreNeverLate) {
  EXPECT_FALSE(LatencyBudget(0).Late(kNow - 10'000'000, kNow, milliseconds(90)));
  const LatencyBudget budget(150);
  EXPECT_FALSE(budget.Late(66'667, kNow, milliseconds(90))) << "a frame clock's stamp";
  EXPECT_FALSE(budget.Late(kNow + 120'000'000, kNow, milliseconds(90))) << "a clock two minutes ahead";
  EXPECT_TRUE(budget.Late(kNow - 59'000'000, kNow, milliseconds(0))) << "within a minute: an age";
}

TEST(RecentDurations, MedianAndSlowestOfTheLastKept) {
  ws::RecentDurations recent(3);
  EXPECT_EQ(recent.Median(), milliseconds(0));
  for (int ms : {50, 10, 20, 30}) recent.Add(milliseconds(ms));  // 50 forgotten
  EXPECT_EQ(recent.Median(), milliseconds(20));
  EXPECT_EQ(recent.Slowest(), milliseconds(30));
}

}  // namespace
