// The process-wide request to stop: SIGINT and SIGTERM make it (ws::Process
// installs the handlers), and long work polls it so that the process exits
// promptly: a calibration's solves (calib/solver/problem.h) and long file reads.
// Work that stops throws Stopped; what it would have saved or published is
// not, since it is not done.
#pragma once

#include <stdexcept>

namespace ws {

struct Stopped : std::runtime_error {
  Stopped() : std::runtime_error("stopped on request (SIGINT or SIGTERM)") {}
};

bool StopRequested();
// Async-signal-safe.
void RequestStop();
// Throws Stopped when a stop was requested.
void ThrowIfStopRequested();

}  // namespace ws
