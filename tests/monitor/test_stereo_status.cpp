// stereo-status in a terminal (tmux), over real udpm: a process killed with
// SIGKILL, which sends no last heartbeat, is shown as gone within 5 s.
#include <signal.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "test_support.h"

namespace {

using namespace ws::test;
using namespace std::chrono_literals;

// A tmux server of this test alone (its socket in the test's folder), with
// one window of `cols` x `rows`.
class Tmux {
 public:
  Tmux(const std::string& command, int cols, int rows) : socket_(TempDir("tmux") + "/socket") {
    const auto r = Run({"new-session", "-d", "-x", std::to_string(cols), "-y", std::to_string(rows), command});
    EXPECT_EQ(r.exit_code, 0) << r.output;
  }
  ~Tmux() { Run({"kill-server"}); }
  std::string Screen() { return Run({"capture-pane", "-p"}).output; }
  // Waits up to `timeout` for the screen to hold a line with both texts.
  bool WaitForLine(const std::string& a, const std::string& b, std::chrono::milliseconds timeout) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    do {
      const std::string screen = Screen();
      for (size_t at = 0; (at = screen.find(a, at)) != std::string::npos; ++at) {
        const size_t end = screen.find('\n', at);
        if (screen.substr(at, end - at).find(b) != std::string::npos) return true;
      }
      std::this_thread::sleep_for(100ms);
    } while (std::chrono::steady_clock::now() < deadline);
    return false;
  }

 private:
  CommandResult Run(std::vector<std::string> args) {
    args.insert(args.begin(), {"/usr/bin/tmux", "-S", socket_});
    return RunCommand(args, 30);
  }
  std::string socket_;
};

TEST(StereoStatus, AKilledProcessIsShownAsGoneWithinFiveSeconds) {
  const std::string dir = TempDir("status-gone"), url = UniqueUdpmUrl();
  Tmux terminal(BinDir() + "/stereo-status --in-url '" + url + "' --log-dir " + dir, 160, 45);
  Command detect({"stereo-detect", "--in-url", url, "--out-url", url, "--log-dir", dir});
  const std::string name = "stereo-detect@", pid = " " + std::to_string(detect.pid()) + " ";
  ASSERT_TRUE(terminal.WaitForLine(name, pid, 30s)) << terminal.Screen();
  detect.Signal(SIGKILL);
  detect.Wait(10);
  ASSERT_TRUE(terminal.WaitForLine(name, "gone", 5s)) << terminal.Screen();
  EXPECT_TRUE(terminal.WaitForLine(name, pid, 0s)) << "the gone process keeps its line: " << terminal.Screen();
}

}  // namespace
