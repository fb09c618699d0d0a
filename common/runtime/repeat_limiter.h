// Repeated log lines, rate-limited with a count. Two lines repeat one
// another when they differ only in their numbers ("frame 17 not used" and
// "frame 18 not used" are one shape). The first line of a shape is written;
// the same shape again within `period` of the last one written is counted,
// not written; the next one written after the period carries the count
// ("… (and 812 like it in the last 10 s, not shown)"). Flush() gives the
// counts still untold, for the end of the log.
//
// Bounded against a peer that varies its text: at most kMaxShapes shapes
// are tracked. When full, shapes idle longer than the period are dropped;
// if none is, new shapes share one slot and are limited together.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <unordered_map>
#include <vector>

namespace ws {

class RepeatLimiter {
 public:
  static constexpr size_t kMaxShapes = 1024;

  explicit RepeatLimiter(int64_t period_us) : period_us_(period_us) {}

  // True when `line` is to be written at now_us; *note is then "" or the
  // count of the lines of its shape not shown since the last one written.
  bool Admit(const std::string& line, int64_t now_us, std::string* note);

  // One line per shape with lines not shown yet: "N lines like 'LINE' not shown".
  std::vector<std::string> Flush();

  // The line with every run of digits replaced by '#'.
  static std::string Shape(const std::string& line);

 private:
  struct Seen {
    int64_t last_written_us = std::numeric_limits<int64_t>::min() / 2;  // never
    int64_t suppressed = 0;
    std::string example;  // the last line not shown
  };
  Seen& Slot(const std::string& shape, int64_t now_us);

  int64_t period_us_;
  std::unordered_map<std::string, Seen> seen_;
  Seen overflow_;  // new shapes while seen_ is full of recent ones
};

}  // namespace ws
