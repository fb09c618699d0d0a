#include "runtime/stage_times.h"

#include <algorithm>

#include <time.h>

namespace ws {
namespace {

float Percentile(std::vector<float> values, double p) {
  const size_t k = std::min(values.size() - 1, size_t(p * double(values.size())));
  std::nth_element(values.begin(), values.begin() + long(k), values.end());
  return values[k];
}

constexpr const char* kPartMark = ": ";

}  // namespace

std::string StagePart(const std::string& stage, const std::string& part) { return stage + kPartMark + part; }

bool IsStagePart(const std::string& name) { return name.find(kPartMark) != std::string::npos; }

void StageTimes::Add(const std::string& stage, double ms) {
  std::lock_guard<std::mutex> lock(mutex_);
  auto [it, added] = stages_.try_emplace(stage);
  if (added) order_.push_back(stage);
  Samples& s = it->second;
  if (s.last.size() < size_t(kWindow))
    s.last.push_back(float(ms));
  else
    s.last[size_t(s.count % kWindow)] = float(ms);
  ++s.count;
}

std::vector<widestereo::stage_time_t> StageTimes::Summary() const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<widestereo::stage_time_t> summary;
  for (const std::string& name : order_) {
    const Samples& s = stages_.at(name);
    widestereo::stage_time_t t;
    t.stage = name;
    t.count = s.count;
    t.window = int32_t(s.last.size());
    t.median_ms = Percentile(s.last, 0.5);
    t.p99_ms = Percentile(s.last, 0.99);
    summary.push_back(t);
  }
  return summary;
}

double ProcessCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

void StageTimer::Stop() {
  if (stopped_) return;
  stopped_ = true;
  times_.Add(stage_, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count());
  if (cpu_start_ms_ >= 0) times_.Add(StagePart(stage_, "CPU"), ProcessCpuMs() - cpu_start_ms_);
}

}  // namespace ws
