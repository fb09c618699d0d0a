#include "runtime/ordered_pipeline.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace ws {

OrderedPipeline::OrderedPipeline(const Options& options) : options_(options) {
  if (options.workers < 1 || options.max_in_flight < 1)
    throw std::invalid_argument("ordered pipeline: needs at least 1 worker and 1 job in flight, not " +
                                std::to_string(options.workers) + " and " +
                                std::to_string(options.max_in_flight));
  for (int i = 0; i < options.workers; ++i) workers_.emplace_back([this] { Work(); });
}

OrderedPipeline::~OrderedPipeline() {
  Drain();
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  work_ready_.notify_all();
  for (std::thread& worker : workers_) worker.join();
}

bool OrderedPipeline::Submit(Job job) {
  std::unique_lock<std::mutex> lock(mutex_);
  if (slots_.size() >= size_t(options_.max_in_flight) && options_.when_full == WhenFull::refuse)
    return false;
  while (slots_.size() >= size_t(options_.max_in_flight)) DeliverOldest(lock);
  slots_.push_back(std::make_unique<Slot>());
  slots_.back()->job = std::move(job);
  peak_in_flight_ = std::max(peak_in_flight_, int(slots_.size()));
  work_ready_.notify_one();
  return true;
}

void OrderedPipeline::Drain() {
  std::unique_lock<std::mutex> lock(mutex_);
  if (options_.when_full == WhenFull::wait)
    while (!slots_.empty()) DeliverOldest(lock);
  else
    job_done_.wait(lock, [this] { return slots_.empty(); });
}

int OrderedPipeline::DropNotStarted() {
  std::lock_guard<std::mutex> lock(mutex_);
  const int dropped = int(slots_.size() - started_);
  slots_.resize(started_);
  job_done_.notify_all();
  return dropped;
}

int OrderedPipeline::in_flight() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return int(slots_.size());
}

int OrderedPipeline::peak_in_flight() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return peak_in_flight_;
}

void OrderedPipeline::Work() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (true) {
    work_ready_.wait(lock, [this] { return stopping_ || started_ < slots_.size(); });
    if (started_ == slots_.size()) return;  // stopping, and nothing left to start
    Slot& slot = *slots_[started_++];
    Job job = std::move(slot.job);
    lock.unlock();
    Delivery delivery = job();
    job = nullptr;  // the job's input goes now, not when the next job comes
    lock.lock();
    slot.delivery = std::move(delivery);
    slot.done = true;
    if (options_.when_full == WhenFull::refuse) DeliverFinished(lock);
    job_done_.notify_all();
  }
}

void OrderedPipeline::DeliverFinished(std::unique_lock<std::mutex>& lock) {
  if (delivering_) return;  // that thread will find this job done too
  delivering_ = true;
  while (!slots_.empty() && slots_.front()->done) DeliverFront(lock);
  delivering_ = false;
}

void OrderedPipeline::DeliverOldest(std::unique_lock<std::mutex>& lock) {
  job_done_.wait(lock, [this] { return slots_.front()->done; });
  DeliverFront(lock);
}

void OrderedPipeline::DeliverFront(std::unique_lock<std::mutex>& lock) {
  Delivery delivery = std::move(slots_.front()->delivery);
  lock.unlock();
  delivery();
  delivery = nullptr;
  lock.lock();
  slots_.pop_front();
  --started_;
}

}  // namespace ws
