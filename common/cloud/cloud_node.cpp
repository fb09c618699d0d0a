#include "cloud/cloud_node.h"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "cloud/pcd_io.h"
#include "lcm_io/channels.h"
#include "runtime/escaped.h"
#include "runtime/output_folder.h"

namespace ws {
namespace {

constexpr const char* kProcessName = "stereo-cloud";

std::string Join(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& line : lines) text += (text.empty() ? "" : "; ") + line;
  return text;
}

// "1167047 points in, 412163 out; plane 1.9996 m, normal (0.0000, 0.0000, -1.0000),
// inlier RMS 1.10 mm (411950 inliers); 2140 ms"
std::string Summary(const PointCloud& in, const CloudFilterResult& result) {
  const auto& s = result.stats;
  double ms = 0;
  for (double stage_ms : s.stage_ms) ms += stage_ms;
  char text[256];
  if (s.plane_found)
    std::snprintf(text, sizeof text,
                  "%d points in, %d out; plane %.4f m, normal (%.4f, %.4f, %.4f), inlier RMS %.2f mm "
                  "(%d inliers); %.0f ms",
                  in.npoints, result.cloud.npoints, s.plane_offset, s.plane_normal[0], s.plane_normal[1],
                  s.plane_normal[2], 1000 * s.inlier_rms, s.stage_points.back(), ms);
  else
    std::snprintf(text, sizeof text, "%d points in, %d out; no plane; %.0f ms", in.npoints,
                  result.cloud.npoints, ms);
  return text;
}

// Runs the chain once on a plane of 320 x 240 points 2 m ahead (a 1280 x
// 960 pair's cloud at every 4th pixel), for nothing: its first run
// allocates and touches what later runs reuse. Live, that first run took
// 70-80 ms against 20 ms for the later ones (bench/transport) and the first
// clouds waited for it; warmed up, the first cloud came 40-75 ms sooner.
void WarmUp(const CloudFilter& filter) {
  PointCloud plane{};
  plane.frame = "warm-up";
  for (int row = 0; row < 240; ++row)
    for (int col = 0; col < 320; ++col)
      plane.xyz.push_back({0.01f * float(col - 160), 0.01f * float(row - 120),
                           2.0f + 0.001f * float((row * 7 + col * 13) % 5)});
  plane.npoints = int(plane.xyz.size());
  try {
    filter.Run(plane);
  } catch (const std::exception&) {  // a chain that rejects it will say so on the first live cloud
  }
}

}  // namespace

CloudNode::CloudNode(Process& process, const CloudFilterConfig& filter, CloudSaveConfig save)
    : process_(process),
      commands_(kProcessName, {{"save", "save [path=NAME.pcd]", {"path", "overwrite"},
                                [this](const CommandArgs& args) { SaveCommand(args); }}}),
      filter_(filter),
      save_(std::move(save)),
      stage_(process.file_input() ? NewestFirst<PointCloud>::Policy::in_line
                                  : NewestFirst<PointCloud>::Policy::newest,
             [this](PointCloud& msg) { Filter(msg); },
             [this](const PointCloud&) {
               process_.CountSkipped(channel::kStereoCloud, "a newer cloud came while filtering");
             }) {
  if (save_.save_every < 0)
    throw ConfigError("--save-every: must be >= 0, got " + std::to_string(save_.save_every));
  if (!save_.pcd_dir.empty()) {
    std::error_code error;
    std::filesystem::create_directories(save_.pcd_dir, error);
    if (error)
      throw std::runtime_error("--pcd-dir: cannot create '" + save_.pcd_dir + "': " + error.message());
  }
  if (!process.file_input()) WarmUp(filter_);
  process_.SetState("filtering");
  process_.AtExit([this] { stage_.Drain(); });
}

CloudNode::~CloudNode() { stage_.Drain(); }

void CloudNode::OnCloud(PointCloud& msg) { stage_.Offer(std::move(msg)); }

void CloudNode::Filter(const PointCloud& msg) {
  CloudFilterResult result;
  try {
    StageTimer timer(process_.stage_times(), "filter", StageTimer::Cpu::process);
    result = filter_.Run(msg);
  } catch (const std::exception& e) {
    return process_.HandleRejected(channel::kStereoCloud, e.what());
  }
  // The filter's own parts, so that the budget says which one to cut.
  for (int i = 0; i < result.stats.nstages; ++i)
    process_.stage_times().Add(StagePart("filter", result.stats.stage_names[size_t(i)]),
                               result.stats.stage_ms[size_t(i)]);
  const std::string frame = "frame " + std::to_string(msg.frame_id);
  process_.log().Detail(frame + ": " + Summary(msg, result));
  if (!result.notes.empty()) process_.log().Detail(frame + ": " + Join(result.notes));
  if (result.cloud.npoints == 0) {
    process_.Counters(channel::kStereoCloud).dropped++;
    if (!in_empty_run_)
      process_.ReportError(frame + ": no usable points in " + std::to_string(msg.npoints) +
                           (result.notes.empty() ? "" : " (" + Join(result.notes) + ")") +
                           "; publishing empty clouds until points come back");
    in_empty_run_ = true;
  } else {
    in_empty_run_ = false;
  }
  process_.Publish(channel::kStereoCloudFiltered, result.cloud);
  process_.Publish(channel::kCloudStats, result.stats);
  std::lock_guard<std::mutex> lock(mutex_);
  ++filtered_;
  newest_stats_ = result.stats;
  newest_ = std::move(result.cloud);
  if (!save_.pcd_dir.empty() && save_.save_every > 0 && filtered_ % save_.save_every == 0) {
    try {
      Save(*newest_, PeriodicPath(*newest_));
    } catch (const std::exception& e) {
      process_.ReportRecurring(e.what());
    }
  }
}

void CloudNode::SaveCommand(const CommandArgs& args) {
  if (save_.pcd_dir.empty()) throw std::runtime_error("save: stereo-cloud was started without --pcd-dir");
  const std::string name = args.Value("path"), overwrite = args.Value("overwrite");
  if (!overwrite.empty() && overwrite != "0" && overwrite != "1")
    throw std::invalid_argument("save: overwrite=" + Quoted(overwrite) + ": 0 or 1");
  std::string path;
  try {
    if (!name.empty()) path = CommandOutputFile({save_.pcd_dir, name, ".pcd", overwrite == "1"});
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("save: path=" + Quoted(name) + ": " + e.what());
  }
  std::lock_guard<std::mutex> lock(mutex_);
  if (!newest_) throw std::runtime_error("save: no cloud has been filtered yet");
  if (const std::string backup = KeepBackup(path); !backup.empty())
    process_.log().Info("save: the previous " + path + " kept as " + backup);
  Save(*newest_, path.empty() ? PeriodicPath(*newest_) : path);
}

std::string CloudNode::Progress() const {
  char line[160];
  std::lock_guard<std::mutex> lock(mutex_);
  if (!newest_) return "clouds 0";
  if (newest_stats_.plane_found)
    std::snprintf(line, sizeof line, "clouds %lld | last %d pts, plane %.3f m, rms %.1f mm | saved %lld",
                  (long long)filtered_, newest_->npoints, newest_stats_.plane_offset,
                  1000 * newest_stats_.inlier_rms, (long long)saved_);
  else
    std::snprintf(line, sizeof line, "clouds %lld | last %d pts, no plane | saved %lld",
                  (long long)filtered_, newest_->npoints, (long long)saved_);
  return line;
}

// A cloud saved by frame id is a new file: a frame id that names one already
// there (a replay, a peer's chosen id) refuses the save.
std::string CloudNode::PeriodicPath(const PointCloud& cloud) const {
  char name[48];
  std::snprintf(name, sizeof name, "cloud_%06lld.pcd", (long long)cloud.frame_id);
  return CommandOutputFile({save_.pcd_dir, name, ".pcd"});
}

void CloudNode::Save(const PointCloud& cloud, const std::string& path) {
  WritePcd(path, cloud);
  ++saved_;
  process_.log().Info("frame " + std::to_string(cloud.frame_id) + ": " +
                      std::to_string(cloud.npoints) + " points written to " + path);
}

}  // namespace ws
