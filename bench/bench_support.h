// What the benchmarks share: timing.
#pragma once

#include <algorithm>
#include <chrono>
#include <functional>
#include <vector>

namespace ws::bench {

// The median (the upper one of an even count) of non-empty values.
inline double Median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

// The wall-clock milliseconds `fn` takes.
inline double Milliseconds(const std::function<void()>& fn) {
  const auto start = std::chrono::steady_clock::now();
  fn();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace ws::bench
