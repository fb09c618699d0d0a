// DownstreamGate with the times given: which pairs may be matched while the
// cloud filter has clouds in hand, and when a commitment is given up.
#include <gtest/gtest.h>

#include "match/downstream_gate.h"

namespace {

using ws::DownstreamGate;
using std::chrono::milliseconds;

const DownstreamGate::Clock::time_point t0{};

TEST(DownstreamGate, OpenUntilAFilterAcknowledgesACloud) {
  DownstreamGate gate;
  for (int id = 1; id <= 5; ++id) EXPECT_TRUE(gate.TryCommit(id, t0)) << id;
}

TEST(DownstreamGate, HoldsAtTwoInHandAndAnAcknowledgementSettlesEveryEarlierPair) {
  DownstreamGate gate;
  ASSERT_TRUE(gate.TryCommit(1, t0));
  gate.Acknowledge(1, t0 + milliseconds(30));
  EXPECT_EQ(gate.in_hand(), 0);
  EXPECT_TRUE(gate.TryCommit(2, t0 + milliseconds(40)));
  EXPECT_TRUE(gate.TryCommit(3, t0 + milliseconds(50)));
  EXPECT_FALSE(gate.TryCommit(4, t0 + milliseconds(60))) << "one filtered, one matched: a third would be replaced";
  EXPECT_EQ(gate.in_hand(), 2);
  gate.Acknowledge(2, t0 + milliseconds(70));
  EXPECT_TRUE(gate.TryCommit(5, t0 + milliseconds(80)));
  // The filter skipped 3 (replaced by 5) or lost it: 5's acknowledgement settles it.
  gate.Acknowledge(5, t0 + milliseconds(120));
  EXPECT_EQ(gate.in_hand(), 0);
}

TEST(DownstreamGate, GivesUpACommitmentAfterFourTimesTheSlowestAcknowledgement) {
  DownstreamGate gate;
  ASSERT_TRUE(gate.TryCommit(1, t0));
  gate.Acknowledge(1, t0 + milliseconds(900));  // patience: 3.6 s
  const auto t1 = t0 + milliseconds(1000);
  ASSERT_TRUE(gate.TryCommit(2, t1));
  ASSERT_TRUE(gate.TryCommit(3, t1));
  EXPECT_FALSE(gate.TryCommit(4, t1 + milliseconds(3500)));
  EXPECT_TRUE(gate.TryCommit(5, t1 + milliseconds(3700))) << "the filter stopped: 2 and 3 given up";
}

TEST(DownstreamGate, WaitsAtLeastTheMinimumPatienceForAFastFilter) {
  DownstreamGate gate;
  ASSERT_TRUE(gate.TryCommit(1, t0));
  gate.Acknowledge(1, t0 + milliseconds(5));
  ASSERT_TRUE(gate.TryCommit(2, t0));
  ASSERT_TRUE(gate.TryCommit(3, t0));
  EXPECT_FALSE(gate.TryCommit(4, t0 + DownstreamGate::kMinPatience - milliseconds(1)));
  EXPECT_TRUE(gate.TryCommit(5, t0 + DownstreamGate::kMinPatience + milliseconds(1)));
}

TEST(DownstreamGate, AFrameIdBackwardsIsARestartedCaptureNotAPairInHand) {
  DownstreamGate gate;
  ASSERT_TRUE(gate.TryCommit(100, t0));
  gate.Acknowledge(100, t0);
  ASSERT_TRUE(gate.TryCommit(101, t0));
  ASSERT_TRUE(gate.TryCommit(102, t0));
  EXPECT_TRUE(gate.TryCommit(0, t0));
  EXPECT_EQ(gate.in_hand(), 1);
}

}  // namespace
