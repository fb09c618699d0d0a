// A process's text log: every line goes to <log_dir>/<name>.log with a
// timestamp, and to the terminal; Progress() keeps one updating status line.
// A line is written escaped (runtime/escaped.h): whatever it holds, it stays
// one line, so a newline in a name from outside cannot forge another.
#pragma once

#include <fstream>
#include <mutex>
#include <string>

namespace ws {

class TextLog {
 public:
  // Creates log_dir if needed; throws std::runtime_error if the file cannot be opened.
  TextLog(const std::string& name, const std::string& log_dir, bool quiet);

  void Info(const std::string& line);
  // Only to the file: per-message detail that would flood the terminal.
  void Detail(const std::string& line);
  void Error(const std::string& line);
  // The one-line progress shown on the terminal (rewritten in place on a TTY).
  void Progress(const std::string& line);
  const std::string& path() const { return path_; }

 private:
  void Write(const char* level, const std::string& line);

  std::string name_;
  std::string path_;
  std::ofstream file_;
  bool quiet_;
  bool tty_;
  bool progress_shown_ = false;
  std::mutex mutex_;
};

}  // namespace ws
