#include "capture/aravis_camera.h"

#include <algorithm>
#include <condition_variable>
#include <deque>
#include <future>
#include <mutex>
#include <thread>
#include <utility>

#include "capture/arv_session.h"
#include "capture/camera_error.h"
#include "capture/frame_id.h"
#include "capture/pixel_format.h"

namespace ws {
namespace {

using Clock = std::chrono::steady_clock;
constexpr size_t kMaxEvents = 100;

CameraFrame ToFrame(ArvBuffer* buffer) {
  size_t size = 0;
  const void* data = arv_buffer_get_image_data(buffer, &size);
  const int width = arv_buffer_get_image_width(buffer);
  const int height = arv_buffer_get_image_height(buffer);
  const uint32_t format = arv_buffer_get_image_pixel_format(buffer);
  gint x_padding = 0;
  gint y_padding = 0;
  arv_buffer_get_image_padding(buffer, &x_padding, &y_padding);
  CameraFrame frame;
  frame.image = PixelsToMat(data, size, width, height,
                            size_t(width) * BytesPerPixel(format) + size_t(x_padding), format);
  frame.frame_id = arv_buffer_get_frame_id(buffer);
  frame.camera_timestamp_ns = int64_t(arv_buffer_get_timestamp(buffer));
  frame.host_timestamp_ns = int64_t(arv_buffer_get_system_timestamp(buffer));
  return frame;
}

// Gives a popped buffer back to its stream when it goes out of scope.
class BorrowedBuffer {
 public:
  BorrowedBuffer(ArvSession& session, ArvBuffer* buffer) : session_(session), buffer_(buffer) {}
  ~BorrowedBuffer() { session_.Push(buffer_); }
  BorrowedBuffer(const BorrowedBuffer&) = delete;
  BorrowedBuffer& operator=(const BorrowedBuffer&) = delete;
  ArvBuffer* get() const { return buffer_; }

 private:
  ArvSession& session_;
  ArvBuffer* buffer_;
};

}  // namespace

class AravisCamera::Impl {
 public:
  Impl(std::string id, ArvCameraSettings settings, AravisCameraOptions options)
      : id_(std::move(id)), settings_(std::move(settings)), options_(options) {
    thread_ = std::thread([this] { ControlLoop(); });
  }

  ~Impl() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
    }
    control_cv_.notify_all();
    connected_cv_.notify_all();
    thread_.join();
  }

  const std::string& id() const { return id_; }

  bool connected() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return session_ != nullptr;
  }

  bool WaitConnected(std::chrono::milliseconds timeout) {
    std::unique_lock<std::mutex> lock(mutex_);
    connected_cv_.wait_for(lock, timeout, [&] { return session_ || stopping_; });
    return session_ != nullptr;
  }

  void RequestTrigger() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (!session_) return;
      trigger_requested_ = true;
    }
    control_cv_.notify_all();
  }

  GrabResult Grab(std::chrono::milliseconds timeout) {
    const auto deadline = Clock::now() + timeout;
    std::shared_ptr<ArvSession> session;
    uint64_t generation = 0;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      connected_cv_.wait_until(lock, deadline, [&] { return session_ || stopping_; });
      session = session_;
      generation = generation_;
    }
    if (!session) return {GrabStatus::disconnected, {}};
    for (;;) {
      ArvBuffer* buffer = session->Pop(
          std::chrono::duration_cast<std::chrono::microseconds>(deadline - Clock::now()));
      if (!buffer) {
        NoteNothingArrived(timeout.count() > 0);
        return {GrabStatus::timeout, {}};
      }
      if (generation == grab_generation_) return Deliver(BorrowedBuffer(*session, buffer));
      // The first buffer of a connection, often late or incomplete (Aravis sizes
      // the socket for the stream only when it arrives): only its id is kept.
      grab_generation_ = generation;
      last_frame_id_ = arv_buffer_get_frame_id(buffer);
      session->Push(buffer);
      NoteAlive();
    }
  }

  CameraCounters counters() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return counters_;
  }

  std::string last_error() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return last_error_;
  }

  std::vector<std::string> TakeEvents() {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<std::string> events(std::make_move_iterator(events_.begin()),
                                    std::make_move_iterator(events_.end()));
    events_.clear();
    return events;
  }

 private:
  void ControlLoop() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!stopping_) {
      if (!session_) {
        lock.unlock();
        std::shared_ptr<ArvSession> session = Open();
        lock.lock();
        if (session)
          Publish(std::move(session));
        else
          control_cv_.wait_for(lock, options_.retry_interval, [&] { return stopping_; });
        continue;
      }
      control_cv_.wait(lock, [&] {
        return stopping_ || trigger_requested_ || check_requested_ || session_->control_lost();
      });
      if (stopping_) break;
      const std::shared_ptr<ArvSession> session = session_;
      const bool trigger = std::exchange(trigger_requested_, false);
      const bool check = std::exchange(check_requested_, false);
      lock.unlock();
      std::string problem = session->control_lost() ? "Aravis lost control of the camera" : "";
      if (problem.empty() && trigger) {
        problem = session->SoftwareTrigger();  // fails only after Aravis's retries
        if (!problem.empty()) problem = "software trigger failed: " + problem;
      }
      if (problem.empty() && check) problem = session->CheckInControl();
      lock.lock();
      if (!problem.empty())
        Drop(problem);
      else if (check)
        last_alive_ = Clock::now();
    }
    if (session_) Retire(std::move(session_));
    std::vector<std::future<void>> closings = std::move(closings_);
    lock.unlock();
    for (auto& closing : closings) closing.wait();
  }

  // One attempt to open the camera, without the lock.
  std::shared_ptr<ArvSession> Open() {
    std::vector<std::string> warnings;
    try {
      auto session = std::make_shared<ArvSession>(
          id_, settings_, options_.n_buffers, [this] { Wake(); }, &warnings);
      std::lock_guard<std::mutex> lock(mutex_);
      for (const std::string& warning : warnings) AddEvent(id_ + ": " + warning);
      return session;
    } catch (const CameraError& e) {
      std::lock_guard<std::mutex> lock(mutex_);
      last_error_ = e.what();
      if (last_error_ != last_open_failure_) {  // once per series of equal failures
        last_open_failure_ = last_error_;
        AddEvent(last_error_ + " (retrying every " +
                 std::to_string(options_.retry_interval.count()) + " ms)");
      }
      return nullptr;
    }
  }

  // The members below "with the lock" are called with mutex_ held.

  void Publish(std::shared_ptr<ArvSession> session) {  // with the lock
    session_ = std::move(session);
    ++generation_;
    if (ever_connected_) ++counters_.reconnects;
    ever_connected_ = true;
    last_alive_ = Clock::now();
    last_open_failure_.clear();
    AddEvent("connected " + session_->description());
    connected_cv_.notify_all();
  }

  void Drop(const std::string& reason) {  // with the lock
    last_error_ = id_ + ": " + reason;
    AddEvent("lost " + last_error_);
    session_->MarkLost();
    Retire(std::move(session_));
  }

  // Closes a session on a thread of its own, once Grab no longer uses it:
  // closing a camera that has gone blocks for Aravis's control timeouts.
  void Retire(std::shared_ptr<ArvSession> session) {  // with the lock
    closings_.erase(std::remove_if(closings_.begin(), closings_.end(),
                                   [](const std::future<void>& closing) {
                                     return closing.wait_for(std::chrono::seconds(0)) ==
                                            std::future_status::ready;
                                   }),
                    closings_.end());
    closings_.push_back(std::async(std::launch::async, [session = std::move(session)]() mutable {
      while (session.use_count() > 1) std::this_thread::sleep_for(std::chrono::milliseconds(1));
      session.reset();
    }));
  }

  void Wake() {
    { std::lock_guard<std::mutex> lock(mutex_); }
    control_cv_.notify_all();
  }

  void AddEvent(std::string text) {  // with the lock
    if (events_.size() == kMaxEvents) events_.pop_front();
    events_.push_back(std::move(text));
  }

  void NoteAlive() {
    std::lock_guard<std::mutex> lock(mutex_);
    last_alive_ = Clock::now();
  }

  void NoteNothingArrived(bool waited) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (waited) ++counters_.timeouts;
    if (Clock::now() - last_alive_ > options_.stall_timeout && !check_requested_) {
      check_requested_ = true;
      control_cv_.notify_all();
    }
  }

  GrabResult Deliver(const BorrowedBuffer& buffer) {
    const uint64_t frame_id = arv_buffer_get_frame_id(buffer.get());
    const uint64_t skipped = FramesSkipped(last_frame_id_, frame_id);
    last_frame_id_ = frame_id;
    GrabResult result{GrabStatus::incomplete, {}};
    std::string problem;
    if (arv_buffer_get_status(buffer.get()) == ARV_BUFFER_STATUS_SUCCESS) {
      try {
        result = {GrabStatus::frame, ToFrame(buffer.get())};
      } catch (const CameraError& e) {
        problem = id_ + ": unreadable frame: " + e.what();
      }
    }
    std::lock_guard<std::mutex> lock(mutex_);
    counters_.lost += skipped;
    ++(result.status == GrabStatus::frame ? counters_.completed : counters_.incomplete);
    last_alive_ = Clock::now();
    if (!problem.empty() && problem != last_error_) {
      last_error_ = problem;
      AddEvent(problem);
    }
    return result;
  }

  const std::string id_;
  const ArvCameraSettings settings_;
  const AravisCameraOptions options_;

  mutable std::mutex mutex_;
  std::condition_variable control_cv_;    // wakes the control thread
  std::condition_variable connected_cv_;  // wakes Grab and WaitConnected
  std::shared_ptr<ArvSession> session_;   // null while disconnected
  uint64_t generation_ = 0;               // of session_
  bool stopping_ = false;
  bool trigger_requested_ = false;
  bool check_requested_ = false;
  bool ever_connected_ = false;
  Clock::time_point last_alive_;  // last frame or successful check
  CameraCounters counters_;
  std::string last_error_;
  std::string last_open_failure_;
  std::deque<std::string> events_;
  std::vector<std::future<void>> closings_;

  // Grab's own (one thread at a time).
  uint64_t grab_generation_ = 0;  // of the session the frames below came from
  uint64_t last_frame_id_ = 0;

  std::thread thread_;  // runs ControlLoop; joined before the members above go
};

AravisCamera::AravisCamera(std::string id, ArvCameraSettings settings, AravisCameraOptions options)
    : impl_(std::make_unique<Impl>(std::move(id), std::move(settings), options)) {}
AravisCamera::~AravisCamera() = default;
const std::string& AravisCamera::id() const { return impl_->id(); }
bool AravisCamera::connected() const { return impl_->connected(); }
bool AravisCamera::WaitConnected(std::chrono::milliseconds timeout) {
  return impl_->WaitConnected(timeout);
}
void AravisCamera::RequestTrigger() { impl_->RequestTrigger(); }
GrabResult AravisCamera::Grab(std::chrono::milliseconds timeout) { return impl_->Grab(timeout); }
CameraCounters AravisCamera::counters() const { return impl_->counters(); }
std::string AravisCamera::last_error() const { return impl_->last_error(); }
std::vector<std::string> AravisCamera::TakeEvents() { return impl_->TakeEvents(); }

}  // namespace ws
