#include "runtime/process.h"

#include <cerrno>
#include <fcntl.h>

#include <signal.h>
#include <unistd.h>

#include <cstdio>
#include <algorithm>
#include <cstring>
#include <exception>
#include <filesystem>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "lcm_io/channels.h"
#include "lcm_io/lcm_log.h"
#include "runtime/large_message_heap.h"
#include "runtime/stop_request.h"
#include "runtime/wall_clock.h"

namespace ws {
namespace {

void OnSignal(int) { RequestStop(); }

void InstallSignalHandlers() {
  struct sigaction action {};
  action.sa_handler = OnSignal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

std::string HostName() {
  char name[256] = {};
  gethostname(name, sizeof name - 1);
  return name;
}

std::unique_ptr<lcm::LCM> OpenLcm(const std::string& url, const char* role) {
  auto lcm = std::make_unique<lcm::LCM>(url);
  if (!lcm->good())
    throw std::runtime_error(std::string("cannot open LCM ") + role + " URL '" +
                             (url.empty() ? "(LCM default)" : url) + "'");
  return lcm;
}

constexpr int64_t kStatusPeriodUs = 1000000;

// " (a newer pair came 9, stereo-cloud had a cloud waiting 3)"; "" without reasons.
std::string SkipReasons(const std::map<std::string, int64_t>& reasons) {
  std::string text;
  for (const auto& [reason, count] : reasons)
    text += (text.empty() ? " (" : ", ") + reason + " " + std::to_string(count);
  return text.empty() ? text : text + ")";
}

}  // namespace

Process::Process(const ProcessOptions& options)
    : options_(options),
      log_(options.name, options.log_dir, options.quiet),
      start_wall_us_(WallMicros()) {
  KeepLargeMessagesInHeap();
  InstallSignalHandlers();
  input_log_ = LcmFileUrlPath(options.in_url);
  file_input_ = message_clock_ = !input_log_.empty();
  sender_ = options.name + "@" + HostName() + " pid " + std::to_string(getpid());
  // Live, nothing signed before the start is accepted: an earlier run may have obeyed it.
  if (!options.key_file.empty())
    auth_.emplace(auth::RigKey::FromFile(options.key_file),
                  file_input_ ? std::numeric_limits<int64_t>::min() : start_wall_us_,
                  int64_t(options.max_clock_skew_s * 1e6));
  if ((file_input_ || options_.batch) && options_.out_url.empty()) {
    const std::string log = options_.batch_out.empty() ? options_.log_dir + "/" + options_.name + ".lcmlog"
                                                       : options_.batch_out;
    std::string written = log;
    if (options_.batch_out_when_done) {
      // Created anew here (never an existing file or a symlink), LCM then
      // opens it; renamed over `log` by the destructor.
      written = log + ".tmp." + std::to_string(getpid());
      const int fd = open(written.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
      if (fd < 0) throw std::runtime_error("cannot write " + written + ": " + std::strerror(errno));
      close(fd);
      batch_pending_ = {written, log};
    }
    options_.out_url = "file://" + std::filesystem::absolute(written).lexically_normal().string() + "?mode=w";
    log_.Info("batch run: output to " + log + ", nothing on the live bus (--out-url URL publishes)");
  }
  out_ = OpenLcm(options_.out_url, "output");
  log_.Info("started (pid " + std::to_string(getpid()) + ", in " +
            (options.in_url.empty() ? "LCM default" : options.in_url) + ", out " +
            (options_.out_url.empty() ? "LCM default" : options_.out_url) +
            (options.config_file.empty() ? "" : ", config " + options.config_file) + ", log " +
            log_.path() + ")");
  if (auth_)
    log_.Info("rig key " + auth_->key().IdText() + " (" + options.key_file +
              "): commands, calibrations, corners and images are signed, and refused unless signed "
              "with it");
  else if (file_input_)  // a batch run obeys no peer: only the log file needs to say it
    log_.Detail("no --key-file: commands, calibrations, corners and images are unauthenticated");
  else
    log_.Info("no --key-file: commands, calibrations, corners and images are unauthenticated (any "
              "peer on the bus may send them)");
}

Process::~Process() {
  if (!complete_events_copy_.empty()) std::remove(complete_events_copy_.c_str());
  if (batch_pending_.first.empty()) return;
  out_.reset();  // closes the log
  const bool done = exit_code_ == 0 && !discard_batch_ && std::uncaught_exceptions() == 0;  // not unwinding an error
  if (!done || std::rename(batch_pending_.first.c_str(), batch_pending_.second.c_str()) != 0)
    std::remove(batch_pending_.first.c_str());
}

void Process::DiscardBatchOutput() { discard_batch_ = true; }

lcm::LCM* Process::Input() {
  if (in_opened_) return in_.get();
  in_opened_ = true;
  if (!file_input_) {
    in_ = OpenLcm(options_.in_url, "input");
    return in_.get();
  }
  const LcmLogScan scan = ScanLcmLog(input_log_);
  std::string url = options_.in_url;
  if (!scan.complete()) {
    input_log_problem = input_log_ + " is damaged: " + scan.problem + "; replaying the " +
                        std::to_string(scan.events) + " complete events before it";
    log_.Error(input_log_problem);
    if (scan.events > 0 && !scan.lcm_replays_exactly) {
      // LCM would not stop exactly there: it reads a copy of what is complete.
      complete_events_copy_ = options_.log_dir + "/" + options_.name + "-" +
                              std::to_string(getpid()) + "-complete-events.lcmlog";
      CopyCompleteEvents(input_log_, scan, complete_events_copy_);
      url = LcmFileUrlWithPath(url, complete_events_copy_);
    }
  }
  if (scan.events > 0) in_ = OpenLcm(url, "input");
  return in_.get();
}

void Process::Every(int64_t period_us, std::function<void()> fn) {
  timers_.push_back({period_us, INT64_MIN, std::move(fn)});
}

void Process::AtEndOfInput(std::function<void()> fn) { at_end_.push_back(std::move(fn)); }

bool Process::Stopping() const { return StopRequested() || exit_code_ != 0; }

void Process::Stop() { RequestStop(); }

void Process::Fatal(const std::string& error) {
  ReportError(error);
  exit_code_ = 1;
}

int Process::Run() {
  lcm::LCM* in = Input();
  bool input_ended = false;
  while (!Stopping()) {
    if (file_input_) {
      if (!in || in->handle() < 0) {
        input_ended = true;
        break;
      }
    } else if (in->handleTimeout(100) < 0 && errno != EINTR) {  // EINTR: a signal, e.g. SIGINT
      Fatal("LCM input failed");
      break;
    }
    Tick();
  }
  if (input_ended) {
    if (!input_log_problem.empty()) ReportError(input_log_problem);
    log_.Info("end of input " + input_log_);
    for (auto& fn : at_end_) {
      if (Stopping()) break;
      try {
        fn();
      } catch (const std::exception& e) {
        Fatal(e.what());
      }
    }
  }
  return Finish();
}

int Process::Finish() {
  for (auto& fn : at_exit_) fn();
  at_exit_.clear();
  // The last heartbeat says it ends, and how: its work done, or stopped by a signal.
  PublishStatus(exit_code_ ? "failed" : StopRequested() ? "stopped" : "exited");
  log_.Detail("final: " + ProgressLine());
  ShowProgress();
  log_.Info(exit_code_ ? "exiting on error" : StopRequested() ? "stopped" : "done");
  return exit_code_;
}

void Process::Tick() {
  const int64_t now = Now();
  if (now != 0 && (last_status_us_ == INT64_MIN || now - last_status_us_ >= kStatusPeriodUs)) {
    last_status_us_ = now;
    PublishStatus();
  }
  for (Timer& timer : timers_) {
    if (now == 0 || now < timer.next_us) continue;
    timer.next_us = now + timer.period_us;
    try {
      timer.fn();
    } catch (const std::exception& e) {
      ReportError(e.what());
    }
  }
  const int64_t wall = WallMicros();
  if (wall - last_progress_wall_us_ >= kStatusPeriodUs) {
    last_progress_wall_us_ = wall;
    ShowProgress();
  }
}

int64_t Process::Now() const { return message_clock_ ? message_utime_.load() : WallMicros(); }

void Process::ObserveTime(int64_t utime) {
  int64_t seen = message_utime_.load();
  while (utime > seen && !message_utime_.compare_exchange_weak(seen, utime)) {
  }
}

void Process::SetState(const std::string& state) {
  std::lock_guard<std::mutex> lock(mutex_);
  state_ = state;
}

void Process::ReportError(const std::string& error) {
  log_.Error(error);
  std::lock_guard<std::mutex> lock(mutex_);
  last_error_ = error;
}

ChannelCounters& Process::Counters(const std::string& channel) {
  std::lock_guard<std::mutex> lock(mutex_);
  auto& slot = counters_[channel];
  if (!slot) slot = std::make_unique<ChannelCounters>();
  return *slot;
}

void Process::ReportRecurring(const std::string& error) {
  log_.Recurring(error);
  std::lock_guard<std::mutex> lock(mutex_);
  last_error_ = error;
}

void Process::HandleRejected(const std::string& channel, const std::string& why) {
  const int64_t so_far = ++Counters(channel).rejected;
  log_.Recurring("rejected on " + channel + " (" + std::to_string(so_far) + " so far): " + why);
  std::lock_guard<std::mutex> lock(mutex_);
  last_error_ = channel + ": " + why;
}

// Frame ids as unsigned, wrap-safe counters: the frames missed between two
// ids are (id - last - 1) mod 2^64, less those that came and were skipped
// undecoded. An id that repeats or steps back a little (a sender started
// anew) starts the count again; one that jumps further than kMaxFrameGap
// either way (a sender's reset, a peer's forged id) does too, and is
// reported, not counted as lost frames.
void Process::CountFrameGap(const std::string& channel, int64_t frame_id, FrameGaps gaps) {
  constexpr uint64_t kMaxFrameGap = 1'000'000;  // 9 h at 30 Hz
  bool reset = false;
  int64_t last = 0;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const uint64_t skipped = uint64_t(std::exchange(undecoded_skips_[channel], 0));
    auto it = last_frame_id_.find(channel);
    if (it != last_frame_id_.end()) {
      last = it->second;
      const uint64_t missed = uint64_t(frame_id) - uint64_t(last) - 1;
      if (missed >= kMaxFrameGap) {
        reset = missed < uint64_t(-1) - kMaxFrameGap;  // not a repeat or a small step back
      } else if (const int64_t gap = int64_t(missed - std::min(missed, skipped)); gaps == FrameGaps::skipped) {
        counters_[channel]->skipped += gap;
        if (gap > 0) skip_reasons_[channel][kPassedOverUpstream] += gap;
      } else {
        counters_[channel]->dropped += gap;
      }
    }
    last_frame_id_[channel] = frame_id;
  }
  if (reset)
    ReportRecurring(channel + ": frame id jumped from " + std::to_string(last) + " to " + std::to_string(frame_id) +
                ": counted as the sender's reset, not as lost frames");
}

void Process::CountSkipped(const std::string& channel, const std::string& reason) {
  Counters(channel).skipped++;
  std::lock_guard<std::mutex> lock(mutex_);
  ++skip_reasons_[channel][reason];
}

void Process::SkipUndecoded(const std::string& channel) {
  Counters(channel).skipped++;
  std::lock_guard<std::mutex> lock(mutex_);
  ++undecoded_skips_[channel];
}

void Process::PublishBytes(const std::string& channel, const std::vector<uint8_t>& bytes) {
  ChannelCounters& counters = Counters(channel);
  int rc;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    rc = out_->publish(channel, bytes.data(), unsigned(bytes.size()));
  }
  if (rc < 0) {
    counters.dropped++;
    ReportRecurring(channel + ": publish failed (" + std::to_string(bytes.size()) + " bytes)");
  } else {
    counters.published++;
  }
}

void Process::PublishStatus(const char* state) {
  widestereo::process_status_t status;
  status.utime = Now();
  status.name = options_.name;
  status.host = HostName();
  status.pid = getpid();
  status.uptime_s = (WallMicros() - start_wall_us_) * 1e-6;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    status.state = state ? state : state_;
    status.last_error = last_error_;
    for (const auto& [name, c] : counters_) {
      widestereo::channel_counters_t cc;
      cc.channel = name;
      cc.received = c->received;
      cc.published = c->published;
      cc.dropped = c->dropped;
      cc.skipped = c->skipped;
      cc.rejected = c->rejected;
      status.channels.push_back(cc);
    }
  }
  status.nchannels = int32_t(status.channels.size());
  status.stages = stage_times_.Summary();
  status.nstages = int32_t(status.stages.size());
  Publish(channel::kProcessStatus, status);
}

void Process::ShowProgress() { log_.Progress(ProgressLine()); }

std::string Process::ProgressLine() {
  std::ostringstream line;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    line << state_;
    for (const auto& [name, c] : counters_) {
      line << " | " << name << " in " << c->received << " out " << c->published;
      if (c->dropped) line << " dropped " << c->dropped;
      if (c->skipped) line << " skipped " << c->skipped << SkipReasons(skip_reasons_[name]);
      if (c->rejected) line << " rejected " << c->rejected;
    }
  }
  if (progress_) line << " | " << progress_();
  return line.str();
}

}  // namespace ws
