// The solver's progress lines (CalibrationOptions::progress) and how numbers
// appear in them and in error messages.
#pragma once

#include <sstream>
#include <string>

#include "calib/solver/options.h"

namespace ws::calib {

inline void Say(const CalibrationOptions& options, const std::string& line) {
  if (options.progress) options.progress(line);
}

inline std::string Fixed(double value, int digits = 4) {
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(digits);
  out << value;
  return out.str();
}

}  // namespace ws::calib
