#include "runtime/text_log.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <stdexcept>

#include "runtime/escaped.h"

namespace ws {
namespace {

std::string WallClockText() {
  const auto now = std::chrono::system_clock::now();
  const std::time_t seconds = std::chrono::system_clock::to_time_t(now);
  const int millis = int(std::chrono::duration_cast<std::chrono::milliseconds>(
                             now.time_since_epoch()).count() % 1000);
  std::tm tm{};
  localtime_r(&seconds, &tm);
  char text[64];
  std::snprintf(text, sizeof text, "%04d-%02d-%02d %02d:%02d:%02d.%03d", tm.tm_year + 1900,
                tm.tm_mon + 1, tm.tm_mday, tm.tm_hour, tm.tm_min, tm.tm_sec, millis);
  return text;
}

int64_t SteadyMicros() {
  return std::chrono::duration_cast<std::chrono::microseconds>(
             std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

TextLog::TextLog(const std::string& name, const std::string& log_dir, bool quiet)
    : name_(name), quiet_(quiet), tty_(isatty(STDERR_FILENO)) {
  std::filesystem::create_directories(log_dir);
  path_ = (std::filesystem::path(log_dir) / (name + ".log")).string();
  file_.open(path_, std::ios::app);
  if (!file_) throw std::runtime_error("cannot open log file " + path_);
}

TextLog::~TextLog() {
  std::lock_guard<std::mutex> lock(mutex_);
  for (const std::string& untold : repeats_.Flush()) EmitLocked("error", untold);
}

void TextLog::Info(const std::string& line) { Write("info", line); }
void TextLog::Detail(const std::string& line) {
  std::lock_guard<std::mutex> lock(mutex_);
  file_ << WallClockText() << " detail " << Escaped(line) << '\n';
}
void TextLog::Error(const std::string& line) { Write("error", line); }
void TextLog::Recurring(const std::string& line) { Write("error", line, true); }

void TextLog::Write(const char* level, const std::string& text, bool limited) {
  std::string line = Escaped(text), repeats;
  std::lock_guard<std::mutex> lock(mutex_);
  if (limited && !repeats_.Admit(line, SteadyMicros(), &repeats)) return;
  EmitLocked(level, line + repeats);
}

void TextLog::EmitLocked(const char* level, const std::string& line) {
  file_ << WallClockText() << ' ' << level << ' ' << line << std::endl;
  if (quiet_ && std::string(level) == "info") return;
  if (progress_shown_) std::fputs("\n", stderr);
  progress_shown_ = false;
  std::fprintf(stderr, "%s: %s\n", name_.c_str(), line.c_str());
}

void TextLog::Progress(const std::string& text) {
  const std::string line = Escaped(text);
  std::lock_guard<std::mutex> lock(mutex_);
  if (quiet_) return;
  if (tty_) {
    std::fprintf(stderr, "\r\033[K%s: %s", name_.c_str(), line.c_str());
    progress_shown_ = true;
  } else {
    std::fprintf(stderr, "%s: %s\n", name_.c_str(), line.c_str());
  }
  std::fflush(stderr);
}

}  // namespace ws
