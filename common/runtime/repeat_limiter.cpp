#include "runtime/repeat_limiter.h"

#include <cctype>

namespace ws {
namespace {

std::string Seconds(int64_t us) { return std::to_string((us + 500'000) / 1'000'000) + " s"; }

}  // namespace

std::string RepeatLimiter::Shape(const std::string& line) {
  std::string shape;
  shape.reserve(line.size());
  for (size_t i = 0; i < line.size(); ++i) {
    if (!std::isdigit(static_cast<unsigned char>(line[i]))) {
      shape += line[i];
      continue;
    }
    shape += '#';
    while (i + 1 < line.size() && std::isdigit(static_cast<unsigned char>(line[i + 1]))) ++i;
  }
  return shape;
}

RepeatLimiter::Seen& RepeatLimiter::Slot(const std::string& shape, int64_t now_us) {
  if (auto it = seen_.find(shape); it != seen_.end()) return it->second;
  if (seen_.size() >= kMaxShapes) {
    // Idle shapes with nothing untold can go; the others must still be said.
    for (auto it = seen_.begin(); it != seen_.end();)
      it = now_us - it->second.last_written_us >= period_us_ && it->second.suppressed == 0 ? seen_.erase(it)
                                                                                            : std::next(it);
    if (seen_.size() >= kMaxShapes) return overflow_;
  }
  return seen_[shape];
}

bool RepeatLimiter::Admit(const std::string& line, int64_t now_us, std::string* note) {
  Seen& seen = Slot(Shape(line), now_us);
  note->clear();
  if (now_us - seen.last_written_us < period_us_) {
    ++seen.suppressed;
    seen.example = line;
    return false;
  }
  if (seen.suppressed > 0)
    *note = " (and " + std::to_string(seen.suppressed) + " like it in the last " +
            Seconds(now_us - seen.last_written_us) + ", not shown)";
  seen.last_written_us = now_us;
  seen.suppressed = 0;
  seen.example.clear();
  return true;
}

std::vector<std::string> RepeatLimiter::Flush() {
  std::vector<std::string> untold;
  auto tell = [&](Seen& seen) {
    if (seen.suppressed == 0) return;
    untold.push_back(std::to_string(seen.suppressed) + " lines like '" + seen.example + "' not shown");
    seen.suppressed = 0;
  };
  for (auto& [shape, seen] : seen_) tell(seen);
  tell(overflow_);
  return untold;
}

}  // namespace ws
