// Helpers for tests that run real processes over real LCM.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "runtime/process_options.h"
#include "widestereo/channel_counters_t.hpp"
#include "widestereo/command_t.hpp"

namespace lcm {
class LCM;
}

namespace ws::test {

// The repository and build folders (from the build's compile definitions).
std::string SourceDir();
std::string BinDir();

// A fresh empty folder under the build tree, unique to this test process.
std::string TempDir(const std::string& name);

// Debian opencv-doc's stereo calibration set: left01..right14.jpg (640x480,
// 9x6 inner corners, pair 10 absent).
inline const char* kOpenCvDataDir = "/usr/share/doc/opencv-doc/examples/data";
// A folder holding links to exactly those 13 pairs (the data folder also has
// an unrelated left.jpg/right.jpg pair).
std::string OpenCvStereoSetDir();

struct CommandResult {
  int exit_code = -1;  // -1: did not exit before the timeout (then killed)
  std::string output;  // stdout and stderr together
};

// argv[0] (a path, or a name in build/bin) running in the background, its
// stdout and stderr going to a file.
class Command {
 public:
  explicit Command(const std::vector<std::string>& argv);
  ~Command();  // kills it if it still runs
  Command(const Command&) = delete;
  Command& operator=(const Command&) = delete;

  int pid() const { return pid_; }
  void Signal(int signal) const;
  // Waits for the exit; after `timeout_s` kills it (exit_code -1).
  CommandResult Wait(double timeout_s);
  std::string Output() const;  // what it printed so far

 private:
  static constexpr int kRunning = -2;
  static inline std::atomic<int> count_{0};
  std::string out_path_;
  int pid_ = -1;
  int exit_code_ = kRunning;
};

// Runs a Command to its end, with a time limit.
CommandResult RunCommand(const std::vector<std::string>& argv, double timeout_s = 60);

// The whole content of a file ("" when it cannot be read).
std::string ReadFileText(const std::string& path);

// A STEREO_COMMAND message (stereo-command's): `command` for `target` ("" =
// every process) with KEY=VALUE arguments.
widestereo::command_t CommandMessage(const std::string& command, const std::string& target = "",
                                     std::vector<std::string> args = {}, int64_t utime = 0);

// A rig key file `dir`/`name` of 32 random bytes with file mode `mode`
// (0600: readable by its owner only, as --key-file requires).
std::string WriteKeyFile(const std::string& dir, const std::string& name, unsigned mode = 0600);

// Kilobytes of resident memory of process `pid`: now (VmRSS) or at its peak
// (VmHWM); a test failure, and 0, when /proc does not say.
long ResidentKb(int pid, const std::string& field);

// AddressSanitizer keeps freed memory in quarantine (256 MB by default), so a
// process's resident memory says nothing about its own use in make test-asan:
// bounds on it are checked only in the normal build.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kMemoryBoundsMeaningful = false;
#else
constexpr bool kMemoryBoundsMeaningful = true;
#endif

// A udpm URL on this host (ttl=0) with a port unique to this test process, so
// tests running at the same time do not hear each other.
std::string UniqueUdpmUrl(int offset = 0);

// A process `name` that listens live on a bus of its own (UniqueUdpmUrl)
// and writes to DIR/out.lcmlog, its log in DIR, quietly.
ws::ProcessOptions LiveInFileOut(const std::string& name, const std::string& dir);

// Handles messages on `lcm` until `done` or `seconds` have passed; returns `done`.
bool HandleUntil(lcm::LCM& lcm, double seconds, const std::function<bool()>& done);

struct LogEvent {
  std::string channel;
  std::vector<uint8_t> data;
  int64_t timestamp = 0;
};

void WriteLog(const std::string& path, const std::vector<LogEvent>& events);
std::vector<LogEvent> ReadLog(const std::string& path);

template <class Msg>
LogEvent Event(const std::string& channel, const Msg& msg, int64_t timestamp = 0) {
  LogEvent e{channel, std::vector<uint8_t>(size_t(msg.getEncodedSize())), timestamp};
  msg.encode(e.data.data(), 0, int(e.data.size()));
  return e;
}

// Decodes every event on `channel` as Msg (events of other types are skipped).
template <class Msg>
std::vector<Msg> Messages(const std::vector<LogEvent>& events, const std::string& channel) {
  std::vector<Msg> out;
  for (const auto& e : events) {
    Msg m;
    if (e.channel == channel && m.decode(e.data.data(), 0, int(e.data.size())) > 0)
      out.push_back(m);
  }
  return out;
}

// The counters of `channel` in the last PROCESS_STATUS that `process` wrote
// to the log at `path` (a test failure, and zeros, when there is none).
widestereo::channel_counters_t LastCounters(const std::string& path, const std::string& process,
                                            const std::string& channel);

}  // namespace ws::test
