// One stage of work on a stream of items (frames, clouds), run on a thread of
// its own so that the input thread keeps draining LCM's queue (Debian's LCM
// 1.3.1 drops the newest message when that queue is full, the very one a
// live consumer wants).
//
// At most one item waits for the stage. What a new item does when one waits
// already depends on the policy:
//   - newest: it takes the waiting one's place, and the replaced item is
//     handed to `dropped` (to be counted): the stage always works on the
//     newest item, never on a backlog, so an item waits at most one work time;
//   - wait: Offer() blocks until the stage takes the waiting one (a later
//     stage of a pipeline: work already done upstream is never thrown away,
//     and the bound holds by back-pressure);
//   - in_line: no thread; Offer() does the work at once on the caller's
//     thread (replay of a log: nothing is lost, and the output interleaves
//     with the caller's own the same way on every replay).
// `work` and `dropped` must not throw; `work` runs on the stage's thread.
#pragma once

#include <condition_variable>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>

namespace ws {

template <class T>
class NewestFirst {
 public:
  enum class Policy { newest, wait, in_line };

  NewestFirst(Policy policy, std::function<void(T&)> work, std::function<void(const T&)> dropped = {})
      : policy_(policy), work_(std::move(work)), dropped_(std::move(dropped)) {
    if (policy_ != Policy::in_line) thread_ = std::thread([this] { Run(); });
  }
  // Finishes what waits and what is in work, then ends the thread.
  ~NewestFirst() {
    Drain();
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
    }
    changed_.notify_all();
    if (thread_.joinable()) thread_.join();
  }
  NewestFirst(const NewestFirst&) = delete;
  NewestFirst& operator=(const NewestFirst&) = delete;

  void Offer(T item) {
    if (policy_ == Policy::in_line) return work_(item);
    std::optional<T> replaced;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      if (policy_ == Policy::wait) changed_.wait(lock, [this] { return !waiting_; });
      if (waiting_) replaced = std::move(waiting_);
      waiting_ = std::move(item);
    }
    changed_.notify_all();
    if (replaced && dropped_) dropped_(*replaced);
  }

  // Returns when nothing waits and nothing is in work.
  void Drain() {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [this] { return !waiting_ && !busy_; });
  }

 private:
  void Run() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (true) {
      changed_.wait(lock, [this] { return stopping_ || waiting_; });
      if (!waiting_) return;  // stopping, and nothing waits
      T item = std::move(*waiting_);
      waiting_.reset();
      busy_ = true;
      lock.unlock();
      changed_.notify_all();  // room for a waiting Offer()
      work_(item);
      lock.lock();
      busy_ = false;
      changed_.notify_all();
    }
  }

  const Policy policy_;
  std::function<void(T&)> work_;
  std::function<void(const T&)> dropped_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::optional<T> waiting_;
  bool busy_ = false;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace ws
