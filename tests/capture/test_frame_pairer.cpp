#include <gtest/gtest.h>

#include "capture/frame_id.h"
#include "capture/frame_pairer.h"

namespace {

constexpr int64_t kMs = 1000000;

ws::CameraFrame At(int64_t host_ms, uint64_t id = 0) {
  ws::CameraFrame frame;
  frame.host_timestamp_ns = host_ms * kMs;
  frame.frame_id = id;
  return frame;
}

TEST(FramePairer, PairsFramesWithinTheTolerance) {
  ws::FramePairer pairer(5 * kMs, 4, ws::PairingClock::host);
  pairer.Add(ws::Side::left, At(100, 1));
  EXPECT_FALSE(pairer.Take());
  pairer.Add(ws::Side::right, At(104, 7));
  const auto pair = pairer.Take();
  ASSERT_TRUE(pair);
  EXPECT_EQ(pair->left.frame_id, 1u);
  EXPECT_EQ(pair->right.frame_id, 7u);
  EXPECT_FALSE(pairer.Waiting(ws::Side::left));
  EXPECT_FALSE(pairer.Waiting(ws::Side::right));
  EXPECT_EQ(pairer.unpaired(ws::Side::left) + pairer.unpaired(ws::Side::right), 0u);
}

TEST(FramePairer, DropsAndCountsFramesThatCanNeverPair) {
  ws::FramePairer pairer(5 * kMs, 4, ws::PairingClock::host);
  pairer.Add(ws::Side::left, At(100, 1));
  pairer.Add(ws::Side::left, At(200, 2));
  pairer.Add(ws::Side::right, At(203, 9));  // the partner of left 2; left 1 has none
  const auto pair = pairer.Take();
  ASSERT_TRUE(pair);
  EXPECT_EQ(pair->left.frame_id, 2u);
  EXPECT_EQ(pairer.unpaired(ws::Side::left), 1u);

  pairer.Add(ws::Side::right, At(300, 10));  // right 10 is older than left 3 by far
  pairer.Add(ws::Side::left, At(400, 3));
  EXPECT_FALSE(pairer.Take());
  EXPECT_EQ(pairer.unpaired(ws::Side::right), 1u);
  EXPECT_TRUE(pairer.Waiting(ws::Side::left));  // left 3 may still find a partner
}

TEST(FramePairer, BoundsTheFramesWaitingForAPartner) {
  ws::FramePairer pairer(5 * kMs, 2, ws::PairingClock::host);
  for (int i = 0; i < 5; ++i) pairer.Add(ws::Side::left, At(100 * i, uint64_t(i)));
  EXPECT_EQ(pairer.unpaired(ws::Side::left), 3u);
  pairer.Add(ws::Side::right, At(300));
  ASSERT_TRUE(pairer.Take());  // left 3 was kept
}

TEST(FramePairer, PairsByCameraClockWhenAsked) {
  ws::FramePairer pairer(5 * kMs, 4, ws::PairingClock::camera);
  ws::CameraFrame left = At(100);
  ws::CameraFrame right = At(100);  // arrived together, exposed 50 ms apart
  left.camera_timestamp_ns = 1000 * kMs;
  right.camera_timestamp_ns = 1050 * kMs;
  pairer.Add(ws::Side::left, left);
  pairer.Add(ws::Side::right, right);
  EXPECT_FALSE(pairer.Take());
  EXPECT_EQ(pairer.unpaired(ws::Side::left), 1u);
}

TEST(FrameId, CountsSkippedIdsAcrossTheSixteenBitWrap) {
  EXPECT_EQ(ws::FramesSkipped(10, 11), 0u);
  EXPECT_EQ(ws::FramesSkipped(10, 14), 3u);
  EXPECT_EQ(ws::FramesSkipped(65535, 1), 0u);  // 0 is never used
  EXPECT_EQ(ws::FramesSkipped(65534, 2), 2u);  // 65535 and 1 missing
  EXPECT_EQ(ws::FramesSkipped(7, 7), 0u);
  EXPECT_EQ(ws::FramesSkipped(100000, 5), 0u);  // a wide counter restarted
}

}  // namespace
