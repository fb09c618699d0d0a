#include "test_support.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <thread>

#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>

#include "widestereo/process_status_t.hpp"

namespace ws::test {

std::string SourceDir() { return WS_SOURCE_DIR; }
std::string BinDir() { return std::string(WS_BINARY_DIR) + "/bin"; }

std::string TempDir(const std::string& name) {
  const auto dir = std::filesystem::path(WS_BINARY_DIR) / "test-tmp" /
                   (name + "-" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

std::string OpenCvStereoSetDir() {
  const std::string dir = TempDir("opencv-stereo-set");
  for (int i = 1; i <= 14; ++i) {
    if (i == 10) continue;
    char name[16];
    for (const char* side : {"left", "right"}) {
      std::snprintf(name, sizeof name, "%s%02d.jpg", side, i);
      std::filesystem::create_symlink(std::string(kOpenCvDataDir) + "/" + name,
                                      std::filesystem::path(dir) / name);
    }
  }
  return dir;
}

Command::Command(const std::vector<std::string>& argv) : out_path_(TempDir("cmd-out-" + std::to_string(++count_)) + "/output.txt") {
  std::string program = argv.at(0);
  if (program.find('/') == std::string::npos && std::filesystem::exists(BinDir() + "/" + program))
    program = BinDir() + "/" + program;
  pid_ = fork();
  if (pid_ == 0) {
    const int fd = open(out_path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(fd, STDOUT_FILENO);
    dup2(fd, STDERR_FILENO);
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args[0] = const_cast<char*>(program.c_str());
    args.push_back(nullptr);
    execvp(args[0], args.data());
    _exit(127);
  }
}

Command::~Command() {
  if (exit_code_ == kRunning) Wait(0);
}

void Command::Signal(int signal) const {
  if (exit_code_ == kRunning) kill(pid_, signal);
}

CommandResult Command::Wait(double timeout_s) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  int status = 0;
  while (exit_code_ == kRunning) {
    if (waitpid(pid_, &status, WNOHANG) == pid_) {
      exit_code_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    } else if (std::chrono::steady_clock::now() > deadline) {
      kill(pid_, SIGKILL);
      waitpid(pid_, &status, 0);
      exit_code_ = -1;
    } else {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  }
  return {exit_code_, Output()};
}

std::string Command::Output() const {
  std::string output;
  FILE* f = std::fopen(out_path_.c_str(), "r");
  char buf[4096];
  size_t n;
  while (f && (n = std::fread(buf, 1, sizeof buf, f)) > 0) output.append(buf, n);
  if (f) std::fclose(f);
  return output;
}

CommandResult RunCommand(const std::vector<std::string>& argv, double timeout_s) {
  return Command(argv).Wait(timeout_s);
}

std::string ReadFileText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

widestereo::command_t CommandMessage(const std::string& command, const std::string& target,
                                     std::vector<std::string> args, int64_t utime) {
  widestereo::command_t msg{};
  msg.utime = utime;
  msg.command = command;
  msg.target = target;
  msg.nargs = int32_t(args.size());
  msg.args = std::move(args);
  return msg;
}

std::string WriteKeyFile(const std::string& dir, const std::string& name, unsigned mode) {
  const std::string path = dir + "/" + name;
  std::random_device random;
  std::string secret(32, '\0');
  for (char& c : secret) c = char(random());
  std::ofstream(path, std::ios::binary) << secret;
  chmod(path.c_str(), mode);
  return path;
}

long ResidentKb(int pid, const std::string& field) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  std::string key;
  long kb = 0;
  while (status >> key)
    if (key == field + ":" && status >> kb) return kb;
  ADD_FAILURE() << "no " << field << " for pid " << pid;
  return 0;
}

std::string UniqueUdpmUrl(int offset) {
  return "udpm://239.255.76.67:" + std::to_string(20000 + (getpid() * 7 + offset) % 20000) +
         "?ttl=0";
}

ws::ProcessOptions LiveInFileOut(const std::string& name, const std::string& dir) {
  ws::ProcessOptions options;
  options.name = name;
  options.in_url = UniqueUdpmUrl();
  options.out_url = "file://" + dir + "/out.lcmlog?mode=w";
  options.log_dir = dir;
  options.quiet = true;
  return options;
}

bool HandleUntil(lcm::LCM& lcm, double seconds, const std::function<bool()>& done) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (!done() && std::chrono::steady_clock::now() < end) lcm.handleTimeout(10);
  return done();
}

void WriteLog(const std::string& path, const std::vector<LogEvent>& events) {
  lcm::LogFile log(path, "w");
  if (!log.good()) throw std::runtime_error("cannot write " + path);
  int64_t n = 0;
  for (const auto& e : events) {
    lcm::LogEvent le;
    le.eventnum = n++;
    le.timestamp = e.timestamp ? e.timestamp : 1000000 * n;
    le.channel = e.channel;
    le.datalen = int32_t(e.data.size());
    le.data = const_cast<uint8_t*>(e.data.data());
    log.writeEvent(&le);
  }
}

std::vector<LogEvent> ReadLog(const std::string& path) {
  lcm::LogFile log(path, "r");
  if (!log.good()) throw std::runtime_error("cannot read " + path);
  std::vector<LogEvent> events;
  while (const lcm::LogEvent* le = log.readNextEvent()) {
    const auto* bytes = static_cast<const uint8_t*>(le->data);
    events.push_back({le->channel, std::vector<uint8_t>(bytes, bytes + le->datalen), le->timestamp});
  }
  return events;
}

widestereo::channel_counters_t LastCounters(const std::string& path, const std::string& process,
                                            const std::string& channel) {
  const auto statuses = Messages<widestereo::process_status_t>(ReadLog(path), "PROCESS_STATUS");
  for (auto s = statuses.rbegin(); s != statuses.rend(); ++s)
    if (s->name == process)
      for (const auto& c : s->channels)
        if (c.channel == channel) return c;
  ADD_FAILURE() << "no counters of " << channel << " from " << process << " in " << path;
  return {};
}

}  // namespace ws::test
