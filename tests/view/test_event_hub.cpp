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

TEST(EventHub, AStreamThatSentTheVersionBeforeGetsTheDeltaAnyOtherTheWhole) {
  EventHub hub;
  EventHub::Cursor first, late;
  int64_t skipped = 0;
  hub.Publish("views", "[a]");
  EXPECT_EQ(*hub.Next(first, 0ms, &skipped)[0].json, "[a]");
  hub.Publish("views", "[a,b]", "+b");
  EXPECT_EQ(*hub.Next(first, 0ms, &skipped)[0].json, "+b");  // it holds [a]
  EXPECT_EQ(*hub.Next(late, 0ms, &skipped)[0].json, "[a,b]");  // it held nothing
  hub.Publish("views", "[a,b,c]", "+c");
  hub.Publish("views", "[b,c]", "-a");
  EXPECT_EQ(*hub.Next(first, 0ms, &skipped)[0].json, "[b,c]");  // it missed +c
  EXPECT_EQ(skipped, 1);
  hub.Publish("views", "[b,c,d]");  // no delta: the whole
  EXPECT_EQ(*hub.Next(first, 0ms, &skipped)[0].json, "[b,c,d]");
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
