// Transport benchmark (bench/transport/run.sh): listens on the bus while
// stereo-capture publishes 2 x 1280x960 GRAY8 pairs at 15 Hz through
// stereo-match and stereo-cloud, and reports
//  - STEREO_IMAGES frames lost in transit (frame-id gaps seen here),
//  - latency from capture (the pair's utime, this host's clock) to the
//    arrival of its STEREO_CLOUD_FILTERED here: median and 99th percentile,
//    over the whole run and again without its first quarter (the processes'
//    start-up: maps built, a browser loading the page),
//  - the pairs whose STEREO_CLOUD_FILTERED never came (skipped for a newer
//    pair or lost on the way), from the first cloud on (pairs sent while
//    the chain's processes were still starting are not counted) and again
//    without the run's first quarter,
//  - every process's drop counters from PROCESS_STATUS,
//  - every process's CPU share between its first and last heartbeat of the
//    run (from /proc/PID/stat: the processes run on this host),
//  - the latency budget: each process's time per frame for each stage of
//    its work (PROCESS_STATUS), and the end-to-end median over the sum of
//    the stage medians on the chain from the capture's stamp on (the closer
//    to 1, the less a frame waits).
// With --prepare DIR it instead writes the simulator's frames as left*/right*
// PNG pairs for stereo-capture --source dir:DIR, and the rig's true
// calibration.yaml for stereo-match.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "lcm_io/channels.h"
#include "rig/rig_file.h"
#include "runtime/process.h"
#include "runtime/process_cli.h"
#include "runtime/wall_clock.h"
#include "source/sim_source.h"
#include "lcm_io/point_cloud.h"
#include "widestereo/stereo_frame_t.hpp"

namespace {

int Prepare(const std::string& sim_config, const std::string& dir) {
  auto source = ws::MakeSimSource(sim_config + "?truth=" + dir + "/truth.yaml", false);
  int n = 0;
  while (auto pair = source->Next()) {
    char name[32];
    std::snprintf(name, sizeof name, "%02d.png", n++);
    cv::imwrite(dir + "/left" + name, pair->left);
    cv::imwrite(dir + "/right" + name, pair->right);
  }
  ws::WriteCalibrationFile(dir + "/calibration.yaml", source->simulator().Truth().rig);
  std::printf("wrote %d pairs and the true calibration.yaml to %s\n", n, dir.c_str());
  return 0;
}

// The stages on the way from a pair's capture stamp to its filtered cloud:
// not the capture's reading of the next pair (the stamp is taken after it),
// nor those of processes beside the chain (stereo-view, this listener).
// A stage's parts ("filter: voxel") are in its own time already.
bool OnTheChain(const std::string& process, const std::string& stage) {
  if (ws::IsStagePart(stage)) return false;
  if (process == "stereo-capture") return stage != "read";
  return process == "stereo-match" || process == "stereo-cloud";
}

// User plus system CPU time of a process of this host, seconds; negative when gone.
double CpuSeconds(int pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const size_t end = text.rfind(')');  // the name may hold spaces
  if (end == std::string::npos) return -1;
  std::istringstream fields(text.substr(end + 2));
  std::string field;
  unsigned long long user = 0, system = 0;
  for (int i = 3; i <= 15 && fields >> field; ++i) {
    if (i == 14) user = std::stoull(field);
    if (i == 15) system = std::stoull(field);
  }
  return double(user + system) / double(sysconf(_SC_CLK_TCK));
}

double Percentile(std::vector<double> values, double p) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  return values[std::min(values.size() - 1, size_t(p * double(values.size())))];
}

// "N of M pairs (P %)": the pairs first..last (frame ids) with no id in
// `clouds`.
std::string Missing(const std::set<int64_t>& clouds, int64_t first, int64_t last) {
  if (first < 0 || last < first) return "no pairs";
  int64_t missing = 0;
  for (int64_t id = first; id <= last; ++id) missing += !clouds.count(id);
  const int64_t due = last - first + 1;
  char text[64];
  std::snprintf(text, sizeof text, "%lld of %lld pairs (%.1f %%)", (long long)missing, (long long)due,
                100.0 * double(missing) / double(due));
  return text;
}

// "a b c ...": of the pairs first..last, how many with no id in `clouds`
// arrived here in each second of the run (`arrival_s`: frame id -> seconds
// after the first pair).
std::string MissingPerSecond(const std::set<int64_t>& clouds, const std::map<int64_t, double>& arrival_s,
                             int64_t first, int64_t last) {
  std::vector<int> per_second;
  for (const auto& [id, t] : arrival_s) {
    if (first < 0 || id < first || id > last) continue;
    const size_t second = size_t(t);
    if (per_second.size() <= second) per_second.resize(second + 1, 0);
    per_second[second] += !clouds.count(id);
  }
  std::string text;
  for (int n : per_second) text += (text.empty() ? "" : " ") + std::to_string(n);
  return text;
}

}  // namespace

int main(int argc, char** argv) {
  ws::ProcessCli cli("bench_transport", "Frames lost and capture-to-filtered-cloud latency on the bus.");
  double duration_s = 60;
  std::string prepare, sim_config = "config/sim/wall.yaml";
  cli.app().add_option("--duration", duration_s, "Seconds to listen, from the first pair");
  cli.app().add_option("--prepare", prepare, "Write the simulator's frames as PNG pairs into this folder and exit");
  cli.app().add_option("--sim", sim_config, "Simulator config for --prepare")->capture_default_str();
  if (auto rc = cli.Parse(argc, argv)) return *rc;
  if (!prepare.empty()) return Prepare(sim_config, prepare);

  ws::Process process(cli.options());
  int64_t first_utime = 0, pairs = 0, first_id = -1, last_id = -1;
  int64_t steady_id = -1;   // the first pair after the first quarter of the run
  int64_t settled_id = -1;  // the last pair a second before the run stops (its cloud had time to come)
  std::vector<double> latency_ms, steady_ms;  // steady: after the first quarter of the run
  std::set<int64_t> cloud_ids;                // the pairs whose filtered cloud came
  std::map<int64_t, double> arrival_s;        // each pair's arrival here, seconds after the first
  std::map<std::string, widestereo::process_status_t> status;
  // Each process's first heartbeat after the first pair, and when it came.
  std::map<std::string, std::pair<widestereo::process_status_t, int64_t>> first_status, last_status;
  std::map<std::string, double> first_cpu, last_cpu;  // CPU seconds at those heartbeats
  process.Subscribe<widestereo::stereo_frame_t>(ws::channel::kStereoImages, [&](const widestereo::stereo_frame_t& f) {
    if (first_id < 0) first_id = f.frame_id, first_utime = ws::WallMicros();
    const int64_t since_first = ws::WallMicros() - first_utime;
    if (steady_id < 0 && since_first >= duration_s * 0.25e6) steady_id = f.frame_id;
    if (since_first <= (duration_s - 1) * 1e6) settled_id = f.frame_id;
    last_id = f.frame_id;
    arrival_s[f.frame_id] = since_first * 1e-6;
    ++pairs;
  });
  process.Subscribe<ws::PointCloud>(ws::channel::kStereoCloudFiltered,
                                               [&](const ws::PointCloud& c) {
                                                 const int64_t now = ws::WallMicros();
                                                 cloud_ids.insert(c.frame_id);
                                                 latency_ms.push_back((now - c.utime) * 1e-3);
                                                 if (first_id >= 0 && now - first_utime >= duration_s * 0.25e6)
                                                   steady_ms.push_back(latency_ms.back());
                                               });
  process.Subscribe<widestereo::process_status_t>(
      ws::channel::kProcessStatus, [&](const widestereo::process_status_t& s) {
        status[s.name] = s;
        if (first_id < 0) return;
        first_status.try_emplace(s.name, s, ws::WallMicros());
        last_status[s.name] = {s, ws::WallMicros()};
        first_cpu.try_emplace(s.name, CpuSeconds(s.pid));
        last_cpu[s.name] = CpuSeconds(s.pid);
      });
  process.Every(200000, [&] {
    if (first_id >= 0 && ws::WallMicros() - first_utime >= duration_s * 1e6) process.Stop();
  });
  const int rc = process.Run();

  const int64_t due = last_id - first_id + 1;
  std::printf("\n%.0f s: %lld pairs of STEREO_IMAGES received here, %lld lost in transit (frame-id gaps)\n", duration_s,
              (long long)pairs, (long long)(due - pairs));
  for (const auto& [name, s] : status)
    for (const auto& c : s.channels)
      if (c.received || c.dropped || c.skipped || c.rejected)
        std::printf("  %-16s %-22s received %6lld skipped %6lld dropped %6lld rejected %lld\n", name.c_str(),
                    c.channel.c_str(), (long long)c.received, (long long)c.skipped, (long long)c.dropped,
                    (long long)c.rejected);
  std::printf("stage rates (published, between each process's first and last heartbeat of the run):\n");
  for (const auto& [name, last] : last_status) {
    const auto& [first, first_us] = first_status.at(name);
    const double seconds = (last.second - first_us) * 1e-6;
    for (const auto& c : last.first.channels) {
      int64_t published_before = 0;  // a channel first published later is not in the first heartbeat
      for (const auto& c0 : first.channels)
        if (c0.channel == c.channel) published_before = c0.published;
      if (c.published > published_before && seconds > 0)
        std::printf("  %-16s %-22s %5.1f Hz\n", name.c_str(), c.channel.c_str(),
                    double(c.published - published_before) / seconds);
    }
  }
  std::printf("CPU (share of one core, between each process's first and last heartbeat of the run):\n");
  for (const auto& [name, last] : last_status) {
    const double seconds = (last.second - first_status.at(name).second) * 1e-6;
    if (seconds > 0 && first_cpu[name] >= 0 && last_cpu[name] >= 0)
      std::printf("  %-16s %5.1f %%\n", name.c_str(), 100 * (last_cpu[name] - first_cpu[name]) / seconds);
  }
  const double median_ms = Percentile(latency_ms, 0.5);
  std::printf("latency budget (time per frame over each process's last frames, at most %d):\n",
              ws::StageTimes::kWindow);
  std::printf("  %-16s %-30s %9s %9s %7s\n", "process", "stage", "median ms", "p99 ms", "frames");
  double compute_ms = 0;
  for (const auto& [name, last] : last_status)
    for (const auto& t : last.first.stages) {
      std::printf("  %-16s %-30s %9.1f %9.1f %7d\n", name.c_str(), t.stage.c_str(), t.median_ms, t.p99_ms, t.window);
      if (OnTheChain(name, t.stage)) compute_ms += t.median_ms;
    }
  std::printf("capture -> STEREO_CLOUD_FILTERED: %zu clouds, latency median %.0f ms, p99 %.0f ms\n", latency_ms.size(),
              median_ms, Percentile(latency_ms, 0.99));
  std::printf("  after the first %.0f s: %zu clouds, latency median %.0f ms, p99 %.0f ms\n", duration_s * 0.25,
              steady_ms.size(), Percentile(steady_ms, 0.5), Percentile(steady_ms, 0.99));
  const int64_t first_cloud = cloud_ids.empty() ? -1 : *cloud_ids.begin();
  std::printf("clouds missing from the first on: %s; after the first %.0f s: %s\n", Missing(cloud_ids, first_cloud, settled_id).c_str(),
              duration_s * 0.25, Missing(cloud_ids, steady_id, settled_id).c_str());
  std::printf("  per second of the run: %s\n",
              MissingPerSecond(cloud_ids, arrival_s, first_cloud, settled_id).c_str());
  if (compute_ms > 0)
    std::printf("latency median / sum of the stage medians after the capture's stamp (%.1f ms): %.2f\n", compute_ms,
                median_ms / compute_ms);
  return rc;
}
