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

// The process's CPU time so far, in ms: every thread's, on every core.
double ProcessCpuMs();

// Times its own lifetime (or until Stop()) as one frame of `stage`. With
// Cpu::process, also the process's CPU time over it, as the part
// "STAGE: CPU": what the stage cost the cores. A busy machine stretches it
// far less than the wall time (a thread waiting for a core spends no CPU
// time), so it compares two builds run in minutes of different load. It
// counts whatever else the process ran meanwhile: meant for a stage that
// has its process's cores to itself (stereo-match's rectify, match and
// cloud, stereo-cloud's filter), their other threads only receiving and
// sending.
class StageTimer {
 public:
  enum class Cpu { no, process };
  StageTimer(StageTimes& times, std::string stage, Cpu cpu = Cpu::no)
      : times_(times),
        stage_(std::move(stage)),
        start_(std::chrono::steady_clock::now()),
        cpu_start_ms_(cpu == Cpu::process ? ProcessCpuMs() : -1) {}
  ~StageTimer() { Stop(); }
  StageTimer(const StageTimer&) = delete;
  StageTimer& operator=(const StageTimer&) = delete;
  void Stop();

 private:
  StageTimes& times_;
  const std::string stage_;
  const std::chrono::steady_clock::time_point start_;
  const double cpu_start_ms_;  // < 0: no CPU time taken
  bool stopped_ = false;
};

}  // namespace ws
