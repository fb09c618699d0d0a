// The solver's progress lines (CalibrationOptions::progress) and how numbers
// appear in them and in error messages.
#pragma once

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

inline std::string Fixed(double value, int digits = 4) {
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(digits);
  out << value;
  return out.str();
}

}  // namespace ws::calib
