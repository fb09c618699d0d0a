#include "launch_fixture.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <thread>

namespace ws::test {

std::vector<std::string> LaunchCommand(const std::string& launch_file, const std::string& lcm_url,
                                       const std::string& run_dir, const std::vector<std::string>& extra) {
  std::vector<std::string> argv = {SourceDir() + "/scripts/launch", SourceDir() + "/" + launch_file,
                                   "--lcm-url", lcm_url, "--run-dir", run_dir};
  // Launches side by side: each page on a free port, not the launch file's one.
  if (ReadFileText(SourceDir() + "/" + launch_file).find("name: stereo-view") != std::string::npos)
    argv.insert(argv.end(), {"--set", "stereo-view.port=0"});
  argv.insert(argv.end(), extra.begin(), extra.end());
  return argv;
}

ChannelListener::ChannelListener(const std::string& lcm_url, const std::string& channel) : bus_(lcm_url) {
  EXPECT_TRUE(bus_.good()) << lcm_url;
  bus_.subscribeFunction(
      channel, +[](const lcm::ReceiveBuffer*, const std::string&, int* heard) { ++*heard; }, &heard_);
}

bool ChannelListener::Hear(int count, std::chrono::steady_clock::time_point not_before) {
  const bool heard = HandleUntil(bus_, 60, [&] { return heard_ >= count && std::chrono::steady_clock::now() >= not_before; });
  heard_ = 0;
  return heard;
}

std::string LaunchLog(const std::string& run_dir) {
  std::ifstream in(run_dir + "/launch.log");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

bool PollUntil(std::chrono::seconds timeout, const std::function<bool()>& done) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (!done()) {
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  return true;
}

int WaitForStart(const std::string& run_dir, const std::string& process, int nth, std::chrono::seconds timeout) {
  const std::string marker = "started " + process + " pid ";
  int pid = -1;
  const bool started = PollUntil(timeout, [&] {
    const std::string log = LaunchLog(run_dir);
    size_t at = 0;
    for (int seen = 0; (at = log.find(marker, at)) != std::string::npos; at += marker.size())
      if (++seen == nth) pid = std::stoi(log.substr(at + marker.size()));
    return pid > 0;
  });
  if (!started) ADD_FAILURE() << "launch.log has no start " << nth << " of " << process << ":\n" << LaunchLog(run_dir);
  return pid;
}

}  // namespace ws::test
