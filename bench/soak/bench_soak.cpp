// Soak run of the whole simulated pipeline at the camera rate, over udpm:
// stereo-capture (sim:, --loop) -> stereo-detect -> stereo-calibrate, and
// stereo-match (started from the simulator's true calibration) ->
// stereo-cloud. Every --solve seconds it sends `solve`, so stereo-calibrate
// solves and publishes STEREO_CALIBRATION and stereo-match rebuilds its maps,
// as in a session where someone recalibrates now and then. Every
// --sample seconds it records each process's resident memory
// (/proc/PID/status) and the counters of its last PROCESS_STATUS in
// OUT/soak.csv. At the end it prints each process's memory (median of the
// first and of the last quarter of the run, and peak), and per channel the
// messages received, dropped and rejected in each quarter: flat memory and
// steady drops mean no leak and no backlog building up.
//
//   build/bench/bench_soak [--duration 1800] [--rate 10] [--solve 300] [--sim config/sim/default.yaml] [--out DIR]
//                          [--source dir:FRAMES --calib FRAMES/calibration.yaml]
// The simulator renders each pair as it goes, slower than 10 Hz on a busy
// 2-core machine; bench/soak/run.sh renders the frames once and plays them
// back from a folder at the camera rate.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>
#include <lcm/lcm-cpp.hpp>

#include "lcm_io/channels.h"
#include "rig/rig_file.h"
#include "sim/simulator.h"
#include "widestereo/command_t.hpp"
#include "widestereo/process_status_t.hpp"

extern char** environ;

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct Child {
  std::string name;
  pid_t pid = -1;
  bool exited = false;
};

// argv[0] started with its output to `output`.
pid_t Spawn(const std::vector<std::string>& argv, const std::string& output) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, output.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = -1;
  const int rc = posix_spawn(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) throw std::runtime_error("cannot start " + argv[0]);
  return pid;
}

long ResidentKb(pid_t pid) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  std::string key;
  long kb = 0;
  while (status >> key)
    if (key == "VmRSS:" && status >> kb) return kb;
  return -1;
}

struct Sample {
  double t_s;
  std::map<std::string, long> rss_kb;                                     // by process
  std::map<std::string, widestereo::channel_counters_t> counters;        // by "process channel"
};

void Summarize(const std::vector<Sample>& samples, const std::vector<Child>& children) {
  if (samples.size() < 2) {
    std::printf("soak: fewer than two samples, nothing to compare\n");
    return;
  }
  // A process's memory moves with its work in flight (stereo-match's SGBM
  // buffers come and go with each frame): compare medians, not two samples.
  const size_t quarter = std::max<size_t>(1, samples.size() / 4);
  auto median_mb = [&](const std::string& name, size_t from, size_t to) {
    std::vector<long> kb;
    for (size_t i = from; i < to; ++i) kb.push_back(samples[i].rss_kb.at(name));
    std::nth_element(kb.begin(), kb.begin() + long(kb.size() / 2), kb.end());
    return kb[kb.size() / 2] / 1024.0;
  };
  std::printf("\nresident memory (MB): median of the first and of the last quarter, peak (%zu samples)\n",
              samples.size());
  for (const Child& child : children) {
    long peak = 0;
    for (const auto& s : samples) peak = std::max(peak, s.rss_kb.at(child.name));
    std::printf("  %-16s %8.1f %8.1f %8.1f\n", child.name.c_str(), median_mb(child.name, 0, quarter),
                median_mb(child.name, samples.size() - quarter, samples.size()), peak / 1024.0);
  }
  std::printf("\nper quarter of the run: received / published / dropped / rejected\n");
  const size_t n = samples.size() - 1;
  for (const auto& [key, end] : samples.back().counters) {
    if (end.received == 0 && end.published == 0) continue;
    std::printf("  %-36s", key.c_str());
    for (int q = 0; q < 4; ++q) {
      const auto& a = samples[q * n / 4].counters;
      const auto& b = samples[(q + 1) * n / 4].counters;
      const auto from = a.count(key) ? a.at(key) : widestereo::channel_counters_t{};
      const auto to = b.count(key) ? b.at(key) : widestereo::channel_counters_t{};
      std::printf("  %5ld/%ld/%ld/%ld", long(to.received - from.received), long(to.published - from.published),
                  long(to.dropped - from.dropped), long(to.rejected - from.rejected));
    }
    std::printf("\n");
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("Soak run of capture (simulator) -> detect -> calibrate, match -> cloud over udpm; memory and drops "
               "over time.");
  double duration_s = 1800, rate_hz = 10, sample_s = 10, solve_s = 300;
  std::string sim_path = "config/sim/default.yaml";
  char stamp[32];
  const std::time_t now = std::time(nullptr);
  std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", std::localtime(&now));
  std::string out = std::string("logs/soak-") + stamp;
  std::string bin = (fs::canonical("/proc/self/exe").parent_path().parent_path() / "bin").string();
  app.add_option("--duration", duration_s, "Seconds to run")->capture_default_str();
  app.add_option("--rate", rate_hz, "Pairs per second from the simulator (config/rig's frame_rate_hz)")
      ->capture_default_str();
  app.add_option("--sample", sample_s, "Seconds between samples")->capture_default_str();
  app.add_option("--solve", solve_s, "Seconds between 'solve' commands to stereo-calibrate")->capture_default_str();
  app.add_option("--sim", sim_path, "Simulator config (its board, and its frames and truth by default)")
      ->capture_default_str();
  std::string source, calib;
  app.add_option("--source", source, "stereo-capture --source (default: sim:SIM)");
  app.add_option("--calib", calib, "Calibration file stereo-match starts from (default: the simulator's truth)");
  app.add_option("--out", out, "Folder for soak.csv and the processes' logs")->capture_default_str();
  app.add_option("--bin", bin, "Folder of the process executables")->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  fs::create_directories(out);
  const ws::SimConfig sim = ws::LoadSimConfig(sim_path);
  if (source.empty()) source = "sim:" + sim_path;
  if (calib.empty()) {
    calib = out + "/true-calibration.yaml";
    ws::WriteCalibrationFile(calib, ws::Simulator(sim).Truth().rig);
  }

  const std::string url = "udpm://239.255.76.67:" + std::to_string(30000 + getpid() % 10000) +
                          "?ttl=0&recv_buf_size=8388608";
  lcm::LCM lcm(url);
  if (!lcm.good()) return std::fprintf(stderr, "bench_soak: cannot open %s\n", url.c_str()), 1;
  std::map<std::string, widestereo::process_status_t> statuses;
  lcm.subscribeFunction(
      ws::channel::kProcessStatus,
      +[](const lcm::ReceiveBuffer* rbuf, const std::string&, std::map<std::string, widestereo::process_status_t>* out) {
        widestereo::process_status_t s;
        if (s.decode(rbuf->data, 0, int(rbuf->data_size)) > 0) (*out)[s.name] = s;
      },
      &statuses);

  const std::vector<std::string> common = {"--in-url", url, "--out-url", url, "--log-dir", out, "--quiet"};
  auto command = [&](const std::string& name, std::vector<std::string> args) {
    args.insert(args.begin(), bin + "/" + name);
    args.insert(args.end(), common.begin(), common.end());
    return Child{name, Spawn(args, out + "/" + name + ".out")};
  };
  std::vector<Child> children = {
      // The run launch's live settings (config/launch/run.yaml).
      command("stereo-cloud", {"--config", "config/stereo-cloud-live.yaml"}),
      command("stereo-match", {"--config", "config/stereo-match-live.yaml", "--calib", calib}),
      command("stereo-calibrate", {"--out", out + "/calibration.yaml"}),
      command("stereo-detect", {"--board", sim.board ? sim.board->board.id : "chessboard:9x6:0.05"}),
  };
  children.push_back(command("stereo-capture", {"--source", source, "--loop", "--rate", std::to_string(rate_hz)}));
  std::printf("soak: %s at %.1f Hz for %.0f s over %s; logs in %s\n", source.c_str(), rate_hz, duration_s,
              url.c_str(), out.c_str());

  std::ofstream csv(out + "/soak.csv");
  csv << "t_s,process,rss_kb,channel,received,published,dropped,rejected\n";
  std::vector<Sample> samples;
  const auto start = Clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
  double next_sample = sample_s, next_solve = solve_s;
  std::string died;
  while (elapsed() < duration_s && died.empty()) {
    lcm.handleTimeout(100);
    if (elapsed() >= next_solve) {
      widestereo::command_t solve{};
      solve.command = "solve";
      solve.target = "stereo-calibrate";
      lcm.publish(ws::channel::kStereoCommand, &solve);
      next_solve += solve_s;
    }
    for (Child& child : children)
      if (waitpid(child.pid, nullptr, WNOHANG) == child.pid) child.exited = true, died = child.name;
    if (elapsed() < next_sample) continue;
    next_sample += sample_s;
    Sample sample{elapsed(), {}, {}};
    for (const Child& child : children) {
      sample.rss_kb[child.name] = ResidentKb(child.pid);
      for (const auto& c : statuses[child.name].channels) {
        sample.counters[child.name + " " + c.channel] = c;
        csv << sample.t_s << ',' << child.name << ',' << sample.rss_kb[child.name] << ',' << c.channel << ','
            << c.received << ',' << c.published << ',' << c.dropped << ',' << c.rejected << '\n';
      }
    }
    csv.flush();
    samples.push_back(sample);
  }
  for (const Child& child : children)
    if (!child.exited) kill(child.pid, SIGINT);
  for (Child& child : children) {
    for (int i = 0; i < 100 && !child.exited; ++i) {
      child.exited = waitpid(child.pid, nullptr, WNOHANG) == child.pid;
      if (!child.exited) std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    if (!child.exited) kill(child.pid, SIGKILL), waitpid(child.pid, nullptr, 0);
  }
  if (!died.empty()) std::printf("soak: %s exited early after %.0f s (see %s)\n", died.c_str(), elapsed(), out.c_str());
  Summarize(samples, children);
  std::printf("\nsamples: %s/soak.csv\n", out.c_str());
  return died.empty() ? 0 : 1;
}
