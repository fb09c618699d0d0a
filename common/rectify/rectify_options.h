// The rectification options on a command line, the same for every process
// that rectifies (stereo-match, stereo-health), so that both rectify alike.
#pragma once

#include <CLI/CLI.hpp>

#include "rectify/rectification.h"

namespace ws {

void AddRectifyOptions(CLI::App& app, RectifyOptions& options);

}  // namespace ws
