#include "interop/number_text.h"

#include <cstdio>

namespace ws {

std::string NumberList(const double* values, int count) {
  std::string out;
  char number[32];
  for (int i = 0; i < count; ++i) {
    std::snprintf(number, sizeof number, "%s%.17g", i ? ", " : "", values[i]);
    out += number;
  }
  return out;
}

}  // namespace ws
