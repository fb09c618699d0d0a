// DownstreamGate with the times given: whether a pair may be matched while
// the cloud filter has clouds in hand, and when a cloud stops counting.
#include <gtest/gtest.h>

#include "match/downstream_gate.h"

namespace {

using ws::DownstreamGate;
using std::chrono::milliseconds;

const DownstreamGate::Clock::time_point t0{};

TEST(DownstreamGate, OpenUntilAFilterAcknowledgesACloud) {
  DownstreamGate gate;
  for (int id = 1; id <= 5; ++id) {
    EXPECT_TRUE(gate.Open(t0)) << id;
    gate.Sent(id, t0);
  }
}

TEST(DownstreamGate, ClosedWhileOneCloudIsFilteredAndAnotherWaits) {
  DownstreamGate gate;
  gate.Sent(1, t0);
  gate.Acknowledge(1, t0 + milliseconds(30));  // the filter acknowledges within 30 ms
  EXPECT_EQ(gate.in_hand(), 0);
  gate.Sent(2, t0 + milliseconds(40));
  EXPECT_TRUE(gate.Open(t0 + milliseconds(45))) << "one being filtered: the next may wait";
  gate.Sent(3, t0 + milliseconds(50));
  EXPECT_FALSE(gate.Open(t0 + milliseconds(60))) << "one filtered, one waiting: a third would replace it";
  EXPECT_EQ(gate.in_hand(), 2);
  gate.Acknowledge(2, t0 + milliseconds(70));
  EXPECT_TRUE(gate.Open(t0 + milliseconds(80)));
  gate.Sent(5, t0 + milliseconds(90));
  // The filter replaced 3 with 5, or 3 was lost: 5's acknowledgement settles it.
  gate.Acknowledge(5, t0 + milliseconds(120));
  EXPECT_EQ(gate.in_hand(), 0);
}

TEST(DownstreamGate, AMatcherSlowerThanTheFilterIsNotHeldBack) {
  DownstreamGate gate;
  // Matching takes 100 ms, the filter acknowledges 60 ms after a cloud is sent.
  ASSERT_TRUE(gate.Open(t0));
  gate.Sent(1, t0 + milliseconds(100));
  ASSERT_TRUE(gate.Open(t0 + milliseconds(100)));
  gate.Acknowledge(1, t0 + milliseconds(160));
  gate.Sent(2, t0 + milliseconds(200));
  ASSERT_TRUE(gate.Open(t0 + milliseconds(200)));
  gate.Sent(3, t0 + milliseconds(300));
  // 2 and 3 not acknowledged yet (the filter ran late), but both will be by
  // the time the next pair's cloud is sent, 100 ms from now.
  EXPECT_TRUE(gate.Open(t0 + milliseconds(300)));
  EXPECT_EQ(gate.in_hand(), 2);
}

TEST(DownstreamGate, AMatcherFasterThanTheFilterIsHeldToItsPace) {
  DownstreamGate gate;
  // Matching takes 100 ms, the filter acknowledges 500 ms after a cloud is sent.
  ASSERT_TRUE(gate.Open(t0));
  gate.Sent(1, t0 + milliseconds(100));
  gate.Acknowledge(1, t0 + milliseconds(600));
  ASSERT_TRUE(gate.Open(t0 + milliseconds(600)));
  gate.Sent(2, t0 + milliseconds(700));
  ASSERT_TRUE(gate.Open(t0 + milliseconds(700)));
  gate.Sent(3, t0 + milliseconds(800));
  EXPECT_FALSE(gate.Open(t0 + milliseconds(800)));
  EXPECT_FALSE(gate.Open(t0 + milliseconds(1000)));
  // 2's slowest acknowledgement is due at 1200, before a cloud matched from
  // 1150 would be sent.
  EXPECT_TRUE(gate.Open(t0 + milliseconds(1150)));
}

TEST(DownstreamGate, ForgetsACloudNeverAcknowledged) {
  DownstreamGate gate;
  gate.Sent(1, t0);
  gate.Acknowledge(1, t0 + milliseconds(900));  // forgotten after 3.6 s
  const auto t1 = t0 + milliseconds(1000);
  gate.Sent(2, t1);
  ASSERT_TRUE(gate.Open(t1 + milliseconds(3500)));
  EXPECT_EQ(gate.in_hand(), 1);
  ASSERT_TRUE(gate.Open(t1 + milliseconds(3700)));
  EXPECT_EQ(gate.in_hand(), 0);
  // Never less than the minimum patience, however fast the filter.
  DownstreamGate fast;
  fast.Sent(1, t0);
  fast.Acknowledge(1, t0 + milliseconds(5));
  fast.Sent(2, t0);
  ASSERT_TRUE(fast.Open(t0 + DownstreamGate::kMinPatience - milliseconds(1)));
  EXPECT_EQ(fast.in_hand(), 1);
  ASSERT_TRUE(fast.Open(t0 + DownstreamGate::kMinPatience + milliseconds(1)));
  EXPECT_EQ(fast.in_hand(), 0);
}

TEST(DownstreamGate, AFrameIdBackwardsIsARestartedCaptureNotACloudInHand) {
  DownstreamGate gate;
  gate.Sent(100, t0);
  gate.Acknowledge(100, t0);
  gate.Sent(101, t0);
  gate.Sent(102, t0);
  gate.Sent(0, t0);
  EXPECT_EQ(gate.in_hand(), 1);
  EXPECT_TRUE(gate.Open(t0));
}

}  // namespace
