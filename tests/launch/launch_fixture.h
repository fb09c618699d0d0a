// Running scripts/launch from a test: its launch.log tells what it did.
#pragma once

#include <chrono>
#include <string>
#include <vector>

#include "test_support.h"

namespace ws::test {

// The launcher on `launch_file` (relative to the repository) with the bus
// `lcm_url`, outputs in `run_dir`, and `extra` arguments.
std::vector<std::string> LaunchCommand(const std::string& launch_file, const std::string& lcm_url,
                                       const std::string& run_dir, const std::vector<std::string>& extra = {});

// The pid of the `nth` start (1: first) of `process` that launch.log in
// `run_dir` records, waiting up to `timeout` for it; -1 (and a test failure) if none.
int WaitForStart(const std::string& run_dir, const std::string& process, int nth, std::chrono::seconds timeout);

// launch.log's text.
std::string LaunchLog(const std::string& run_dir);

}  // namespace ws::test
