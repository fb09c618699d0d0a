#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <future>
#include <thread>
#include <vector>

#include "runtime/newest_first.h"

namespace {

using Stage = ws::NewestFirst<int>;

TEST(NewestFirst, WorksOnTheNewestItemAndHandsTheReplacedOnesToDropped) {
  std::promise<void> release;
  std::shared_future<void> released = release.get_future().share();
  std::atomic<bool> first_taken{false};
  std::vector<int> worked, dropped;  // worked: the stage's thread; dropped: this one
  {
    Stage stage(
        Stage::Policy::newest,
        [&](int& item) {
          first_taken = true;
          if (item == 0) released.wait();  // hold the stage busy on item 0
          worked.push_back(item);
        },
        [&](const int& item) { dropped.push_back(item); });
    stage.Offer(0);
    while (!first_taken) std::this_thread::yield();
    for (int i = 1; i <= 5; ++i) stage.Offer(i);  // 1..4 replaced in turn by the next
    release.set_value();
    stage.Drain();
    EXPECT_EQ(worked, (std::vector<int>{0, 5}));
    EXPECT_EQ(dropped, (std::vector<int>{1, 2, 3, 4}));
  }
}

TEST(NewestFirst, WaitPolicyLosesNothingAndKeepsTheOrder) {
  std::vector<int> worked;
  {
    Stage stage(Stage::Policy::wait, [&](int& item) {
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
      worked.push_back(item);
    });
    for (int i = 0; i < 20; ++i) stage.Offer(i);
  }  // the destructor finishes what waits
  std::vector<int> expected(20);
  for (int i = 0; i < 20; ++i) expected[i] = i;
  EXPECT_EQ(worked, expected);
}

TEST(NewestFirst, InLineWorksOnTheCallersThreadBeforeOfferReturns) {
  std::thread::id worker;
  int last = -1;
  Stage stage(Stage::Policy::in_line, [&](int& item) {
    worker = std::this_thread::get_id();
    last = item;
  });
  stage.Offer(7);
  EXPECT_EQ(last, 7);
  EXPECT_EQ(worker, std::this_thread::get_id());
}

}  // namespace
