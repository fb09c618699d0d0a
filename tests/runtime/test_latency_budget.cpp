// LatencyBudget with the times given: which frames are late.
#include <gtest/gtest.h>

#include "runtime/latency_budget.h"
#include "runtime/recent_durations.h"

namespace {

using ws::LatencyBudget;
using std::chrono::milliseconds;

constexpr int64_t kNow = 1'800'000'000'000'000;  // microseconds of the wall clock

TEST(LatencyBudget, LateWhenTheAgePlusTheRestExceedsTheBudget) {
  LatencyBudget budget(150);
  EXPECT_FALSE(budget.Late(kNow - 60'000, kNow, milliseconds(90))) << "60 + 90 ms: on the budget";
  EXPECT_TRUE(budget.Late(kNow - 61'000, kNow, milliseconds(90)));
  EXPECT_TRUE(budget.Late(kNow - 151'000, kNow, milliseconds(0)));
}

// Skipped, a frame would only leave the stage idle when the next could not
// make it either: no frame of the last ones was young enough.
TEST(LatencyBudget, NoFrameIsLateWhileNoFresherOneCouldMakeIt) {
  LatencyBudget budget(150);
  EXPECT_FALSE(budget.Late(kNow - 100'000, kNow, milliseconds(60))) << "none younger seen";
  EXPECT_FALSE(budget.Late(kNow - 10'000, kNow, milliseconds(60)));
  EXPECT_TRUE(budget.Late(kNow - 100'000, kNow, milliseconds(60))) << "one 10 ms old made it";
  EXPECT_FALSE(budget.Late(kNow - 100'000, kNow, milliseconds(145))) << "10 + 145 ms: not even the youngest";
  for (size_t i = 0; i < LatencyBudget::kAges; ++i) budget.Late(kNow - 100'000, kNow, milliseconds(200));
  EXPECT_FALSE(budget.Late(kNow - 100'000, kNow, milliseconds(60))) << "the young one forgotten";
}

TEST(LatencyBudget, NoBoundAndStampsOfAnotherClockAreNeverLate) {
  EXPECT_FALSE(LatencyBudget(0).Late(kNow - 10'000'000, kNow, milliseconds(90)));
  LatencyBudget budget(150);
  EXPECT_FALSE(budget.Late(kNow - 1'000, kNow, milliseconds(0)));
  EXPECT_FALSE(budget.Late(66'667, kNow, milliseconds(0))) << "a frame clock's stamp";
  EXPECT_FALSE(budget.Late(kNow + 120'000'000, kNow, milliseconds(0))) << "a clock two minutes ahead";
  EXPECT_TRUE(budget.Late(kNow - 59'000'000, kNow, milliseconds(0))) << "within a minute: an age";
}

TEST(RecentDurations, MedianSlowestAndFastestOfTheLastKept) {
  ws::RecentDurations recent(3);
  EXPECT_EQ(recent.Median(), milliseconds(0));
  for (int ms : {5, 10, 20, 30}) recent.Add(milliseconds(ms));  // 5 forgotten
  EXPECT_EQ(recent.Median(), milliseconds(20));
  EXPECT_EQ(recent.Slowest(), milliseconds(30));
  EXPECT_EQ(recent.Fastest(), milliseconds(10));
}

}  // namespace
