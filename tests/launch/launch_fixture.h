// Running scripts/launch from a test: its launch.log tells what it did.
#pragma once

#include <chrono>
#include <functional>
#include <lcm/lcm-cpp.hpp>
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

// Messages on one channel of a launch's bus, heard by the test: it acts
// once a process has published, not after a guessed time.
class ChannelListener {
 public:
  ChannelListener(const std::string& lcm_url, const std::string& channel);
  // Waits up to 60 s until `count` messages have arrived since the last
  // call (or the listener's start) and `not_before` has passed.
  bool Hear(int count, std::chrono::steady_clock::time_point not_before = {});

 private:
  lcm::LCM bus_;
  int heard_ = 0;
};

// launch.log's text.
std::string LaunchLog(const std::string& run_dir);

// Checks `done` (a file the launch writes: nothing to be told of) every
// 100 ms for up to `timeout`; returns whether it held.
bool PollUntil(std::chrono::seconds timeout, const std::function<bool()>& done);

}  // namespace ws::test
