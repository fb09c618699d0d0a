// stereo-cloud's work: runs the filter chain on every cloud of STEREO_CLOUD,
// publishes the result on STEREO_CLOUD_FILTERED and what each stage did on
// CLOUD_STATS (one of each per input cloud, empty or not, so that consumers
// can pair them by frame_id), and writes filtered clouds as PCD files.
//
// PCD files: with a pcd_dir, every save_every-th filtered cloud goes to
// <pcd_dir>/cloud_<frame_id>.pcd. A `save` command on STEREO_COMMAND (target
// "" or "stereo-cloud") writes the newest filtered cloud into pcd_dir, as
// cloud_<frame_id>.pcd or as its argument path=NAME.pcd, a plain file name
// (runtime/output_folder.h); without pcd_dir it is an error. Commands
// aimed at other processes, or at all processes but not ours ("solve"), are
// ignored; an unknown command aimed at stereo-cloud is rejected.
//
// Each cloud gets a line in the log file: points in and out, the plane
// (distance, normal, inlier RMS) or "no plane", the time taken.
//
// Live, the chain runs on a thread of its own and takes the newest cloud
// waiting (runtime/newest_first.h): a cloud replaced before the chain took it
// is counted as skipped on STEREO_CLOUD, so that the output stays about one
// chain time behind the input, whatever its rate; the chain is run once at
// start on a made-up plane (nothing published), so that the first clouds do
// not wait for what its first run allocates. From a log, every cloud is
// filtered, in line.
//
// Counting: a cloud that fails validation is rejected (by Process); a valid
// cloud from which nothing usable remains (empty, all NaN or out of range,
// all one point) is published empty and counted as dropped on STEREO_CLOUD,
// and the first of a run of such clouds is reported as an error. A failed
// `save` is a rejected STEREO_COMMAND; a failed periodic write is reported.
#pragma once

#include <cstdint>
#include <mutex>
#include <optional>
#include <string>

#include "cloud/cloud_filter.h"
#include "runtime/command_dispatcher.h"
#include "runtime/newest_first.h"
#include "runtime/process.h"
#include "widestereo/command_t.hpp"
#include "lcm_io/point_cloud.h"

namespace ws {

struct CloudSaveConfig {
  std::string pcd_dir;  // "" : no periodic files; `save` needs path=
  int save_every = 1;   // with pcd_dir: every N-th filtered cloud (0: only on `save`)
};

class CloudNode {
 public:
  // Creates pcd_dir. Throws ConfigError for an invalid filter config or a
  // negative save_every, std::runtime_error when pcd_dir cannot be created.
  CloudNode(Process& process, const CloudFilterConfig& filter, CloudSaveConfig save);
  ~CloudNode();

  // Takes the cloud (moves it to the filter's stage).
  void OnCloud(PointCloud& msg);
  // Throws (so Process counts the command as rejected) when a `save` fails.
  void OnCommand(const widestereo::command_t& command) { commands_.Dispatch(command); }
  // "clouds 12 | last 40211 pts, plane 2.003 m, rms 4.1 mm | saved 3"
  std::string Progress() const;

 private:
  void Filter(const PointCloud& msg);
  std::string PeriodicPath(const PointCloud& cloud) const;
  void Save(const PointCloud& cloud, const std::string& path);
  // save [path=NAME.pcd] [overwrite=0|1]: the newest filtered cloud.
  void SaveCommand(const CommandArgs& args);

  Process& process_;
  const CommandDispatcher commands_;
  const CloudFilter filter_;
  const CloudSaveConfig save_;
  mutable std::mutex mutex_;  // guards what follows, but for the stage
  std::optional<PointCloud> newest_;
  widestereo::cloud_stats_t newest_stats_{};
  int64_t filtered_ = 0;
  int64_t saved_ = 0;
  bool in_empty_run_ = false;
  NewestFirst<PointCloud> stage_;  // last: drained before the rest goes
};

}  // namespace ws
