// Numbers as the other tools' text formats take them: every digit a double
// has (%.17g), so that a file read back gives the very numbers written.
#pragma once

#include <string>

namespace ws {

// "a, b, c" (no brackets).
std::string NumberList(const double* values, int count);

}  // namespace ws
