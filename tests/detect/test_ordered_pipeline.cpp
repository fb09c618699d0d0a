// The ordered pipeline: results in input order whatever the workers' timing,
// a bounded number of jobs in flight, refusal when full live, back-pressure
// and deliveries at fixed points when replaying.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <random>
#include <thread>
#include <vector>

#include "runtime/ordered_pipeline.h"

namespace {

using ws::OrderedPipeline;
using WhenFull = OrderedPipeline::WhenFull;

// A job that takes a random 0-3 ms and delivers its number.
OrderedPipeline::Job NumberJob(int number, std::vector<int>& delivered, std::mutex& mutex) {
  const int sleep_us = int(std::mt19937(number)() % 3000);
  return [number, sleep_us, &delivered, &mutex] {
    std::this_thread::sleep_for(std::chrono::microseconds(sleep_us));
    return OrderedPipeline::Delivery([number, &delivered, &mutex] {
      std::lock_guard<std::mutex> lock(mutex);
      delivered.push_back(number);
    });
  };
}

TEST(OrderedPipeline, DeliversInSubmissionOrderInBothModes) {
  for (WhenFull mode : {WhenFull::refuse, WhenFull::wait}) {
    std::vector<int> delivered, accepted;
    std::mutex mutex;
    {
      OrderedPipeline pipeline({3, 5, mode});
      for (int i = 0; i < 200; ++i) {
        if (pipeline.Submit(NumberJob(i, delivered, mutex))) accepted.push_back(i);
        if (i % 7 == 0) std::this_thread::sleep_for(std::chrono::milliseconds(1));
      }
      pipeline.Drain();
      EXPECT_EQ(pipeline.in_flight(), 0);
      EXPECT_LE(pipeline.peak_in_flight(), 5);
    }
    EXPECT_EQ(delivered, accepted);
    if (mode == WhenFull::wait) {
      EXPECT_EQ(accepted.size(), 200u);
    }
  }
}

TEST(OrderedPipeline, WhenFullLiveRefusesTheNewestJob) {
  std::atomic<bool> release{false};
  std::vector<int> delivered;
  std::mutex mutex;
  OrderedPipeline pipeline({2, 3, WhenFull::refuse});
  auto blocked = [&](int number) {
    return [&, number] {
      while (!release) std::this_thread::sleep_for(std::chrono::milliseconds(1));
      return OrderedPipeline::Delivery([&, number] {
        std::lock_guard<std::mutex> lock(mutex);
        delivered.push_back(number);
      });
    };
  };
  EXPECT_TRUE(pipeline.Submit(blocked(0)));
  EXPECT_TRUE(pipeline.Submit(blocked(1)));
  EXPECT_TRUE(pipeline.Submit(blocked(2)));  // waits for a worker
  EXPECT_FALSE(pipeline.Submit(blocked(3)));
  EXPECT_FALSE(pipeline.Submit(blocked(4)));
  EXPECT_EQ(pipeline.in_flight(), 3);
  release = true;
  pipeline.Drain();
  EXPECT_EQ(delivered, (std::vector<int>{0, 1, 2}));
  EXPECT_TRUE(pipeline.Submit(blocked(5)));  // room again
  pipeline.Drain();
  EXPECT_EQ(delivered.back(), 5);
}

TEST(OrderedPipeline, ReplayDeliversJobKDuringSubmissionOfJobKPlusMaxInFlight) {
  constexpr int kMaxInFlight = 3;
  std::vector<int> delivered_before_submit;  // deliveries seen when each Submit returns
  std::vector<int> delivered;
  std::mutex mutex;
  OrderedPipeline pipeline({2, kMaxInFlight, WhenFull::wait});
  for (int i = 0; i < 20; ++i) {
    ASSERT_TRUE(pipeline.Submit(NumberJob(i, delivered, mutex)));
    std::lock_guard<std::mutex> lock(mutex);
    delivered_before_submit.push_back(int(delivered.size()));
  }
  for (int i = 0; i < 20; ++i) EXPECT_EQ(delivered_before_submit[i], std::max(0, i + 1 - kMaxInFlight));
  pipeline.Drain();
  EXPECT_EQ(delivered.size(), 20u);
}

TEST(OrderedPipeline, DestructionDeliversEverythingAccepted) {
  std::vector<int> delivered;
  std::mutex mutex;
  {
    OrderedPipeline pipeline({2, 8, WhenFull::refuse});
    for (int i = 0; i < 8; ++i) ASSERT_TRUE(pipeline.Submit(NumberJob(i, delivered, mutex)));
  }
  EXPECT_EQ(delivered, (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7}));
}

TEST(OrderedPipeline, NeedsAWorkerAndRoomForAJob) {
  EXPECT_THROW(OrderedPipeline({0, 4, WhenFull::wait}), std::invalid_argument);
  EXPECT_THROW(OrderedPipeline({2, 0, WhenFull::wait}), std::invalid_argument);
}

}  // namespace
