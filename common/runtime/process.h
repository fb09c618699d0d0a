// What every widestereo process shares at run time: its LCM input and output,
// typed and validated subscriptions, per-channel counters, the 1 Hz
// PROCESS_STATUS heartbeat, the text log, clean exit on SIGINT/SIGTERM, and
// exit at the end of a file:// input log, so every process is also a
// log-to-log filter.
//
// Authentication. With --key-file, every message type that carries an
// auth_t (commands, calibrations, corners, images) is signed by Publish and
// checked by Subscribe (auth/message_auth.h): one that fails is rejected with
// the reason.
// Without a key they go unsigned and unchecked, and the log says so at start.
//
// Batch runs. With a file:// input (or files the process reads itself,
// ProcessOptions::batch) and no --out-url, the output goes to a log file
// (ProcessOptions::batch_out), never to the LCM default: a replay on a
// robot's network must not reach the live rig.
//
// Clock. Live, the process clock is the wall clock. With a file:// input it is
// the utime of the newest input message, so that timers and heartbeats fall at
// the same places in the output on every replay of the same log.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include <lcm/lcm-cpp.hpp>

#include "auth/message_auth.h"
#include "lcm_io/decode.h"
#include "runtime/library_log.h"
#include "runtime/process_options.h"
#include "runtime/stage_times.h"
#include "runtime/text_log.h"
#include "widestereo/process_status_t.hpp"

namespace ws {

struct ChannelCounters {
  std::atomic<int64_t> received{0};
  std::atomic<int64_t> published{0};
  std::atomic<int64_t> dropped{0};  // lost
  std::atomic<int64_t> skipped{0};  // replaced by a newer frame, by design
  std::atomic<int64_t> rejected{0};
};

class Process {
 public:
  // What the frame ids missing between a subscription's messages are:
  //  - count: lost (dropped), on a channel that carries every frame;
  //  - skipped: passed over by the sender by design, on a channel that
  //    carries only the frames a newest-frame or once-a-second sender
  //    looked at (STEREO_CORNERS, CALIBRATION_HEALTH): counted as skipped,
  //    reason kPassedOverUpstream (a message lost in transit there cannot
  //    be told from one not sent, and is counted so too);
  //  - ignore: not counted at all (CLOUD_STATS read by stereo-match as
  //    acknowledgements).
  enum class FrameGaps { count, skipped, ignore };
  static constexpr const char* kPassedOverUpstream = "passed over by the sender";

  // Opens the text log, the rig key (if any) and both LCM URLs; throws
  // std::runtime_error with the reason when one cannot be opened.
  explicit Process(const ProcessOptions& options);
  // With ProcessOptions::batch_out_when_done, puts the batch output log in
  // place (exit code 0, not destroyed by an exception) or removes it.
  ~Process();
  // With batch_out_when_done: the batch output log is removed at the end
  // whatever the exit code (a run stopped before its work).
  void DiscardBatchOutput();

  // Decodes, validates and counts every message on `channel`, then calls
  // `handler` with it (the handler may move what it keeps out of it: the
  // message is the handler's). A message that fails to decode or validate, or whose handler
  // throws, is counted as rejected and logged; the process goes on. Gaps in
  // a message's frame_id are counted as dropped (lost upstream or in transit).
  // Live, at most `queue_capacity` messages wait for the handler (0: LCM's
  // default); LCM drops the oldest beyond that, which shows as a frame_id gap.
  template <class Msg>
  void Subscribe(const std::string& channel, std::function<void(Msg&)> handler,
                 int queue_capacity = 0, FrameGaps gaps = FrameGaps::count);
  // As Subscribe, for a consumer that samples the stream (stereo-view shows a
  // few of the image pairs that arrive): a message that comes while `due()`
  // is false is counted as skipped and not handled. Live it is skipped
  // before it is even decoded; from a file:// log once its time is observed
  // (the log's clock). Frame-id gaps are counted net of those skips.
  template <class Msg>
  void SubscribeSampled(const std::string& channel, std::function<bool()> due,
                        std::function<void(Msg&)> handler, int queue_capacity = 0,
                        FrameGaps gaps = FrameGaps::count);

  // Encodes and publishes; thread-safe. A failed publish is counted as
  // dropped. A message that carries an auth_t is signed (with a rig key).
  template <class Msg>
  void Publish(const std::string& channel, const Msg& msg);

  // Calls fn every period_us of the process clock (from Run() or Tick()).
  void Every(int64_t period_us, std::function<void()> fn);
  // Calls fn once when a file:// input log has been read to its end.
  void AtEndOfInput(std::function<void()> fn);
  // Calls fn once before the last heartbeat, however the process ends (work
  // still in hand on other threads is finished and counted there).
  void AtExit(std::function<void()> fn) { at_exit_.push_back(std::move(fn)); }
  // Adds a line to the terminal progress display.
  void SetProgress(std::function<std::string()> fn) { progress_ = std::move(fn); }

  // Handles input until the end of a file:// input or a stop, then Finish().
  int Run();
  // The last heartbeat (state "exited": its work done; "stopped": by SIGINT
  // or SIGTERM, its log's last line "stopped"; "failed") and log line;
  // returns the exit code. For processes
  // that run their own loop (stereo-capture) instead of Run().
  int Finish();
  // Heartbeat, timers and progress; for processes that run their own loop.
  void Tick();
  bool Stopping() const;
  // Ends Run() cleanly, as SIGINT does.
  void Stop();
  // Ends Run() with exit code 1 after logging the error.
  void Fatal(const std::string& error);

  int64_t Now() const;
  // Advances the message clock (no effect live).
  void ObserveTime(int64_t utime);
  bool file_input() const { return file_input_; }
  // Makes the clock follow ObserveTime() even without file input (a source
  // process writing a log, for example).
  void UseMessageClock() { message_clock_ = true; }

  void SetState(const std::string& state);
  // Logs an error and keeps it as the status's last_error.
  void ReportError(const std::string& error);
  // The same for an error that can come once a message or a frame: logged
  // at most once every TextLog::kRepeatPeriodUs a shape, with the count.
  void ReportRecurring(const std::string& error);
  ChannelCounters& Counters(const std::string& channel);
  // Counts a frame on `channel` as skipped on purpose (whole, before work
  // was spent on it) and why: the progress line and the final log line
  // give each reason's count, "skipped 12 (a newer pair came 9, stereo-cloud
  // had a cloud waiting 3)". Thread-safe.
  void CountSkipped(const std::string& channel, const std::string& reason);
  // Counts a message on `channel` as rejected and logs why (as
  // ReportRecurring); for handlers that work on another thread.
  void HandleRejected(const std::string& channel, const std::string& why);
  TextLog& log() { return log_; }
  // The per-frame time of each stage, reported in PROCESS_STATUS. Receiving
  // and publishing messages that carry a frame_id are timed here ("receive
  // CHANNEL": decode, validate and the handler; "publish CHANNEL": encode and
  // send); a process times its own stages with StageTimer.
  StageTimes& stage_times() { return stage_times_; }
  const ProcessOptions& options() const { return options_; }

 private:
  struct Timer {
    int64_t period_us;
    int64_t next_us;
    std::function<void()> fn;
  };

  // The input LCM, opened on first use; null for an empty input log.
  lcm::LCM* Input();
  void PublishBytes(const std::string& channel, const std::vector<uint8_t>& bytes);
  // The heartbeat, with `state` instead of the process's own if given.
  void PublishStatus(const char* state = nullptr);
  void ShowProgress();
  // State, per-channel counters and the process's own progress, on one line.
  std::string ProgressLine();
  void CountFrameGap(const std::string& channel, int64_t frame_id, FrameGaps gaps);
  // Counts a message skipped before it was decoded (SubscribeSampled).
  void SkipUndecoded(const std::string& channel);

  ProcessOptions options_;
  TextLog log_;
  LibraryLog library_log_{log_};  // glog's messages (Ceres's) into log_
  std::optional<auth::AuthCheck> auth_;  // with --key-file
  std::string sender_;                   // "stereo-command@robot pid 4242"
  std::unique_ptr<lcm::LCM> in_;
  bool in_opened_ = false;
  std::unique_ptr<lcm::LCM> out_;
  std::pair<std::string, std::string> batch_pending_;  // with batch_out_when_done: temporary, final
  bool discard_batch_ = false;
  std::string input_log_;        // path of a file:// input, "" live
  std::string input_log_problem; // where a damaged input log stops
  std::string complete_events_copy_;  // what LCM reads of a damaged input log, if not the log
  bool file_input_ = false;
  bool message_clock_ = false;
  std::atomic<int64_t> message_utime_{0};
  int64_t start_wall_us_;
  int64_t last_status_us_ = INT64_MIN;
  int64_t last_progress_wall_us_ = 0;
  int exit_code_ = 0;

  std::mutex mutex_;  // guards state_, last_error_, counters_ creation, publishing
  std::string state_ = "running";
  std::string last_error_;
  std::map<std::string, std::unique_ptr<ChannelCounters>> counters_;
  std::map<std::string, int64_t> last_frame_id_;
  std::map<std::string, int64_t> undecoded_skips_;  // since the channel's last frame id
  std::map<std::string, std::map<std::string, int64_t>> skip_reasons_;  // channel -> reason -> count
  std::vector<Timer> timers_;
  std::vector<std::function<void()>> at_end_;
  std::vector<std::function<void()>> at_exit_;
  std::function<std::string()> progress_;
  std::vector<std::shared_ptr<void>> handler_contexts_;
  StageTimes stage_times_;
};

namespace detail {
template <class Msg, class = void>
struct HasFrameId : std::false_type {};
template <class Msg>
struct HasFrameId<Msg, std::void_t<decltype(std::declval<Msg>().frame_id)>> : std::true_type {};
}  // namespace detail

template <class Msg>
void Process::Subscribe(const std::string& channel, std::function<void(Msg&)> handler,
                        int queue_capacity, FrameGaps gaps) {
  SubscribeSampled<Msg>(channel, nullptr, std::move(handler), queue_capacity, gaps);
}

template <class Msg>
void Process::SubscribeSampled(const std::string& channel, std::function<bool()> due,
                               std::function<void(Msg&)> handler, int queue_capacity, FrameGaps gaps) {
  Counters(channel);
  lcm::LCM* in = Input();
  if (!in) return;  // an empty input log: nothing will arrive
  struct Context {
    Process* self;
    std::function<bool()> due;  // null: every message is handled
    std::function<void(Msg&)> handler;
    FrameGaps gaps;
  };
  auto context = std::make_shared<Context>(Context{this, std::move(due), std::move(handler), gaps});
  handler_contexts_.push_back(context);
  lcm::Subscription* subscription = in->subscribeFunction(
      channel,
      +[](const lcm::ReceiveBuffer* rbuf, const std::string& ch, Context* ctx) {
        Process* self = ctx->self;
        self->Counters(ch).received++;
        if (ctx->due && !self->file_input_ && !ctx->due()) return self->SkipUndecoded(ch);
        std::optional<StageTimer> timer;
        if constexpr (detail::HasFrameId<Msg>::value) timer.emplace(self->stage_times_, "receive " + ch);
        try {
          Msg msg = DecodeMessage<Msg>(rbuf->data, int(rbuf->data_size));
          self->ObserveTime(msg.utime);
          if constexpr (auth::IsAuthenticated<Msg>::value)
            if (self->auth_)
              self->auth_->Check(ch, msg, static_cast<const uint8_t*>(rbuf->data), rbuf->data_size, self->Now());
          if constexpr (detail::HasFrameId<Msg>::value)
            if (ctx->gaps != FrameGaps::ignore) self->CountFrameGap(ch, msg.frame_id, ctx->gaps);
          if (ctx->due && self->file_input_ && !ctx->due()) {
            self->Counters(ch).skipped++;
            return;
          }
          ctx->handler(msg);
        } catch (const std::exception& e) {
          self->HandleRejected(ch, e.what());
        }
      },
      context.get());
  if (queue_capacity > 0 && !file_input_) subscription->setQueueCapacity(queue_capacity);
}

template <class Msg>
void Process::Publish(const std::string& channel, const Msg& msg) {
  std::optional<StageTimer> timer;
  if constexpr (detail::HasFrameId<Msg>::value) timer.emplace(stage_times_, "publish " + channel);
  std::vector<uint8_t> bytes;
  try {
    if constexpr (auth::IsAuthenticated<Msg>::value)
      bytes = auth_ ? auth::EncodeSigned(auth_->key(), channel, sender_, Now(), msg)
                    : auth::EncodeWithAuth(msg, widestereo::auth_t{});
    else
      bytes = EncodeMessage(msg);
  } catch (const std::invalid_argument& e) {
    Counters(channel).dropped++;
    ReportRecurring(channel + ": " + e.what());
    return;
  }
  PublishBytes(channel, bytes);
}

}  // namespace ws
