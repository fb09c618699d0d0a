#include <gtest/gtest.h>

#include "fake_cameras/exposure_index.h"

namespace {

constexpr int64_t kMs = 1000000;
using ws::Side;

TEST(ExposureIndex, FramesExposedTogetherShareAnIndex) {
  ws::ExposureIndex index(20 * kMs);
  EXPECT_EQ(index.Assign(Side::left, 1000 * kMs, false), 0);
  EXPECT_EQ(index.Assign(Side::right, 1001 * kMs, false), 0);
  EXPECT_EQ(index.Assign(Side::right, 1100 * kMs, false), 1);  // right first this time
  EXPECT_EQ(index.Assign(Side::left, 1120 * kMs, false), 1);
  EXPECT_EQ(index.Assign(Side::left, 1200 * kMs, false), 2);
  EXPECT_EQ(index.Assign(Side::right, 1221 * kMs, false), 3);  // too far apart: two moments
}

TEST(ExposureIndex, ASideNeverTakesTheSameIndexTwice) {
  ws::ExposureIndex index(20 * kMs);
  EXPECT_EQ(index.Assign(Side::left, 1000 * kMs, false), 0);
  EXPECT_EQ(index.Assign(Side::left, 1005 * kMs, false), 1);
  EXPECT_EQ(index.Assign(Side::right, 1006 * kMs, false), 1);
}

TEST(ExposureIndex, AMissedTriggerCostsOneFrameNotTheStep) {
  ws::ExposureIndex index(20 * kMs);
  EXPECT_EQ(index.Assign(Side::left, 0, false), 0);
  EXPECT_EQ(index.Assign(Side::right, 5 * kMs, false), 0);
  EXPECT_EQ(index.Assign(Side::left, 100 * kMs, false), 1);  // right missed this trigger
  EXPECT_EQ(index.Assign(Side::right, 205 * kMs, false), 2);
  EXPECT_EQ(index.Assign(Side::left, 200 * kMs, false), 2);
}

TEST(ExposureIndex, TheFirstFrameOfAStreamStartsNoMoment) {
  ws::ExposureIndex index(20 * kMs);
  EXPECT_EQ(index.Assign(Side::left, 0, false), 0);
  EXPECT_EQ(index.Assign(Side::right, 0, false), 0);
  EXPECT_EQ(index.Assign(Side::right, 90 * kMs, true), 0);  // late, after a reconnection
  EXPECT_EQ(index.Assign(Side::left, 100 * kMs, false), 1);
  EXPECT_EQ(index.Assign(Side::right, 101 * kMs, false), 1);
}

TEST(ExposureIndex, StaysInStepWhenOneSideWasAway) {
  ws::ExposureIndex index(20 * kMs);
  EXPECT_EQ(index.Assign(Side::left, 0, false), 0);
  EXPECT_EQ(index.Assign(Side::right, 0, false), 0);
  for (int i = 1; i <= 5; ++i)
    EXPECT_EQ(index.Assign(Side::left, i * 100 * kMs, false), i);  // right away
  EXPECT_EQ(index.Assign(Side::right, 595 * kMs, false), 6);       // back, just before left
  EXPECT_EQ(index.Assign(Side::left, 600 * kMs, false), 6);
  EXPECT_EQ(index.Assign(Side::left, 700 * kMs, false), 7);
  EXPECT_EQ(index.Assign(Side::right, 710 * kMs, false), 7);
}

}  // namespace
