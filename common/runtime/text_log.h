// A process's text log: every line goes to <log_dir>/<name>.log with a
// timestamp, and to the terminal; Progress() keeps one updating status line.
// A line is written escaped (runtime/escaped.h): whatever it holds, it stays
// one line, so a newline in a name from outside cannot forge another.
// Recurring() is for an error that can come once a message (a peer's, a
// frame's): lines of one shape within kRepeatPeriodUs are counted, not
// written (runtime/repeat_limiter.h); the count goes with the next one
// written, and what is still untold is written when the log closes. Info
// and Error write every line: what they say is bounded by the input (a
// folder's files, a solve's warnings), and each names its own file.
#pragma once

#include <fstream>
#include <mutex>
#include <string>

#include "runtime/repeat_limiter.h"

namespace ws {

class TextLog {
 public:
  static constexpr int64_t kRepeatPeriodUs = 10'000'000;

  // Creates log_dir if needed; throws std::runtime_error if the file cannot be opened.
  TextLog(const std::string& name, const std::string& log_dir, bool quiet);
  ~TextLog();

  void Info(const std::string& line);
  // Only to the file: per-message detail that would flood the terminal.
  void Detail(const std::string& line);
  void Error(const std::string& line);
  void Recurring(const std::string& line);
  // The one-line progress shown on the terminal (rewritten in place on a TTY).
  void Progress(const std::string& line);
  const std::string& path() const { return path_; }

 private:
  void Write(const char* level, const std::string& line, bool limited = false);
  // To the file and, unless quiet and info, the terminal; mutex_ held.
  void EmitLocked(const char* level, const std::string& line);

  std::string name_;
  std::string path_;
  std::ofstream file_;
  bool quiet_;
  bool tty_;
  bool progress_shown_ = false;
  RepeatLimiter repeats_{kRepeatPeriodUs};
  std::mutex mutex_;
};

}  // namespace ws
