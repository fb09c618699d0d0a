// A process's latency budget: how long each stage of its work takes per
// frame. Stages are timed on whatever thread runs them; PROCESS_STATUS
// carries each stage's median and 99th percentile over its last kWindow
// frames (widestereo::stage_time_t). A stage may also report its parts,
// named "STAGE: PART" (StagePart): they are timed inside it, so a reader
// that adds stages up skips them (IsStagePart).
#pragma once

#include <chrono>
#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "widestereo/stage_time_t.hpp"

namespace ws {

class StageTimes {
 public:
  static constexpr int kWindow = 1024;

  // Thread-safe.
  void Add(const std::string& stage, double ms);
  // Every stage timed so far, in the order first timed.
  std::vector<widestereo::stage_time_t> Summary() const;

 private:
  struct Samples {
    int64_t count = 0;
    std::vector<float> last;  // a ring of the last kWindow times
  };
  mutable std::mutex mutex_;
  std::vector<std::string> order_;
  std::map<std::string, Samples> stages_;
};

// "filter: voxel": the part `part` of the stage `stage`.
std::string StagePart(const std::string& stage, const std::string& part);
bool IsStagePart(const std::string& name);

// Times its own lifetime (or until Stop()) as one frame of `stage`.
class StageTimer {
 public:
  StageTimer(StageTimes& times, std::string stage)
      : times_(times), stage_(std::move(stage)), start_(std::chrono::steady_clock::now()) {}
  ~StageTimer() { Stop(); }
  StageTimer(const StageTimer&) = delete;
  StageTimer& operator=(const StageTimer&) = delete;
  void Stop() {
    if (stopped_) return;
    stopped_ = true;
    times_.Add(stage_, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count());
  }

 private:
  StageTimes& times_;
  const std::string stage_;
  const std::chrono::steady_clock::time_point start_;
  bool stopped_ = false;
};

}  // namespace ws
