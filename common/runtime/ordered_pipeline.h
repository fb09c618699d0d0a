// A work queue that runs jobs on several threads and delivers their results
// in the order the jobs came in, with a bounded number of jobs in flight.
//
// A job runs on a worker thread and returns its delivery: the step that hands
// its result on (publishes it, counts it). Deliveries run one at a time, in
// submission order. A job is "in flight" from Submit() until its delivery
// has run, so at most max_in_flight jobs (and their inputs and results) are
// held at any time.
//
// When max_in_flight jobs are in flight, Submit() either
//   - refuses the new job (WhenFull::refuse, live input). The newest frame is
//     the one to lose: it costs nothing yet (not copied, not decoded), while
//     every accepted job has its place in the output order and may be half
//     done; refusing keeps the output a gap-free subsequence in input order,
//     and the caller counts the refusal as a drop. Deliveries run on the
//     workers, as soon as the oldest job is done, so results go out with no
//     added latency.
//   - or waits (WhenFull::wait, replay of a log): back-pressure, nothing is
//     lost. Deliveries then run on the submitting thread, only when it must
//     make room (and in Drain()): the result of job k goes out during the
//     submission of job k + max_in_flight, whatever the threads' timing, so
//     a replay interleaves its output with everything else the submitting
//     thread does identically every time.
//
// Jobs and deliveries must not throw: catch inside and deliver the failure.
// Submit() and Drain() are called from one thread (the input's).
#pragma once

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace ws {

class OrderedPipeline {
 public:
  using Delivery = std::function<void()>;
  using Job = std::function<Delivery()>;

  enum class WhenFull { refuse, wait };

  struct Options {
    int workers = 2;
    int max_in_flight = 4;  // at least 1
    WhenFull when_full = WhenFull::refuse;
  };

  explicit OrderedPipeline(const Options& options);
  // Drains, then stops the workers.
  ~OrderedPipeline();

  OrderedPipeline(const OrderedPipeline&) = delete;
  OrderedPipeline& operator=(const OrderedPipeline&) = delete;

  // Queues a job; false when it was refused (WhenFull::refuse and full).
  bool Submit(Job job);
  // Returns when every accepted job has been delivered.
  void Drain();
  // Forgets the accepted jobs no worker has started (a live process
  // stopping: what it has not begun it need not finish); their count.
  int DropNotStarted();

  int in_flight() const;
  // The most jobs that were ever in flight at once.
  int peak_in_flight() const;

 private:
  struct Slot {
    Job job;
    Delivery delivery;
    bool done = false;
  };

  void Work();
  // Runs the deliveries of the finished jobs at the head of the queue, on
  // this thread, unless another thread is delivering already. Keeps `lock`.
  void DeliverFinished(std::unique_lock<std::mutex>& lock);
  // Waits for the oldest job and runs its delivery (WhenFull::wait).
  void DeliverOldest(std::unique_lock<std::mutex>& lock);
  // Runs the oldest job's delivery (it is done) without the lock, then drops it.
  void DeliverFront(std::unique_lock<std::mutex>& lock);

  const Options options_;
  mutable std::mutex mutex_;
  std::condition_variable work_ready_;  // a job to start, or stopping
  std::condition_variable job_done_;    // a job finished, or a delivery ran
  std::deque<std::unique_ptr<Slot>> slots_;  // in flight, oldest first
  size_t started_ = 0;      // slots_[0 .. started_) have been taken by workers
  bool delivering_ = false;  // a thread is running deliveries
  bool stopping_ = false;
  int peak_in_flight_ = 0;
  std::vector<std::thread> workers_;
};

}  // namespace ws
