// The solver's progress lines (CalibrationOptions::progress) and how numbers
// appear in them and in error messages.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <mutex>
#include <sstream>
#include <string>

#include "calib/solver/options.h"

namespace ws::calib {

// One progress line; the lines of solves running at once (each camera of a
// rig, several models) are passed on one at a time.
inline void Say(const CalibrationOptions& options, const std::string& line) {
  static std::mutex mutex;
  if (!options.progress) return;
  std::lock_guard<std::mutex> lock(mutex);
  options.progress(line);
}

// The wall-clock seconds since `start`.
inline double Seconds(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// "about 12 s left": the seconds since `start` per item done, times the
// items still to do (of `total`; a ladder that may stop early: "at most").
inline std::string TimeLeft(std::chrono::steady_clock::time_point start, int done, int total) {
  if (done <= 0) return "";
  std::ostringstream out;
  out << "about " << std::lround(Seconds(start) / done * std::max(0, total - done)) << " s left";
  return out.str();
}

inline std::string Fixed(double value, int digits = 4) {
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(digits);
  out << value;
  return out.str();
}

}  // namespace ws::calib
