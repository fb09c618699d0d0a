// The page's hub: every stream gets each topic's newest event; a stream that
// does not keep up misses versions, counted, and never holds up Publish.
#include <gtest/gtest.h>

#include <thread>

#include "view/event_hub.h"

namespace {

using ws::view::EventHub;
using namespace std::chrono_literals;

TEST(EventHub, AStreamGetsEachTopicsNewestAndCountsWhatItMissed) {
  EventHub hub;
  EventHub::Cursor cursor;
  int64_t skipped = 0;
  hub.Publish("frame", "1");
  hub.Publish("frame", "2");  // before the stream came: not missed by it
  auto events = hub.Next(cursor, 0ms, &skipped);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(*events[0].json, "2");
  EXPECT_EQ(skipped, 0);
  for (int i = 3; i <= 7; ++i) hub.Publish("frame", std::to_string(i));
  hub.Publish("cloud", "a");
  events = hub.Next(cursor, 0ms, &skipped);
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(events[0].topic, "cloud");
  EXPECT_EQ(*events[1].json, "7");
  EXPECT_EQ(skipped, 4);  // 3 to 6
  EXPECT_TRUE(hub.Next(cursor, 0ms, &skipped).empty());
  hub.Publish("frame", "8");
  hub.Publish("frame", "9");
  EXPECT_EQ(hub.Unsent(cursor), 2);
}

TEST(EventHub, PublishNeverWaitsForAStreamAndCloseWakesIt) {
  EventHub hub;
  EventHub::Cursor stalled;  // a stream that never asks again
  int64_t skipped = 0;
  hub.Publish("frame", "0");
  hub.Next(stalled, 0ms, &skipped);
  for (int i = 1; i <= 100000; ++i) hub.Publish("frame", std::string(100, 'x'));
  EXPECT_EQ(hub.Unsent(stalled), 100000);
  std::thread waiting([&] {
    EventHub::Cursor cursor;
    hub.Next(cursor, 0ms, &skipped);
    EXPECT_TRUE(hub.Next(cursor, 60s, &skipped).empty());  // woken by Close, not the timeout
  });
  std::this_thread::sleep_for(50ms);
  hub.Close();
  waiting.join();
  EXPECT_TRUE(hub.closed());
}

}  // namespace
