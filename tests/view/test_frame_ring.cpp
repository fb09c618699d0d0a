// The frames held for thumbnails: found by id and utime, the oldest
// forgotten beyond the count or the bytes held.
#include <gtest/gtest.h>

#include <memory>

#include "view/frame_ring.h"

namespace {

using ws::view::FrameRing;

std::shared_ptr<const widestereo::stereo_frame_t> Frame(int64_t id, size_t bytes) {
  auto frame = std::make_shared<widestereo::stereo_frame_t>();
  frame->frame_id = id;
  frame->utime = 1000 * id;
  frame->left.data.resize(bytes);
  return frame;
}

TEST(FrameRing, FindsAFrameByIdAndUtimeAndForgetsTheOldestBeyondTheCount) {
  FrameRing ring;
  for (int64_t id = 0; id < int64_t(FrameRing::kFramesHeld) + 3; ++id) ring.Hold(Frame(id, 10));
  EXPECT_EQ(ring.frames(), FrameRing::kFramesHeld);
  EXPECT_FALSE(ring.Find(2, 2000)) << "forgotten: the oldest go first";
  ASSERT_TRUE(ring.Find(3, 3000));
  EXPECT_EQ(ring.Find(3, 3000)->frame_id, 3);
  EXPECT_FALSE(ring.Find(3, 3001)) << "another frame of the same id (a restarted capture)";
  ring.Clear();
  EXPECT_EQ(ring.frames(), 0u);
  EXPECT_EQ(ring.bytes(), 0u);
  EXPECT_FALSE(ring.Find(40, 40000));
}

TEST(FrameRing, HoldsAtMostItsBytes) {
  FrameRing ring;
  const size_t third = FrameRing::kBytesHeld / 3 + 1;
  for (int64_t id = 0; id < 4; ++id) ring.Hold(Frame(id, third));
  EXPECT_EQ(ring.frames(), 2u);
  EXPECT_LE(ring.bytes(), FrameRing::kBytesHeld);
  EXPECT_TRUE(ring.Find(3, 3000));
  ring.Hold(Frame(9, FrameRing::kBytesHeld + 1));  // larger than the whole budget: held by no one
  EXPECT_EQ(ring.frames(), 0u);
  EXPECT_EQ(ring.bytes(), 0u);
}

}  // namespace
