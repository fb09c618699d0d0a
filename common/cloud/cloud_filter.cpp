#include "cloud/cloud_filter.h"

#include <chrono>

#include <pcl/console/print.h>

#include "cloud/cloud_stages.h"
#include "cloud/plane_fit.h"

namespace ws {
namespace {

// Records, for each stage, the points it left and the time since the
// previous stage ended.
class StageClock {
 public:
  void Lap(const char* stage, size_t points) {
    const Clock::time_point now = Clock::now();
    stats_.stage_names.push_back(stage);
    stats_.stage_points.push_back(int32_t(points));
    stats_.stage_ms.push_back(std::chrono::duration<double, std::milli>(now - last_).count());
    stats_.nstages = int32_t(stats_.stage_names.size());
    last_ = now;
  }

  // The stage fields of a cloud_stats_t; the rest zero.
  widestereo::cloud_stats_t stats() const { return stats_; }

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point last_ = Clock::now();
  widestereo::cloud_stats_t stats_{};
};

PclCloud::Ptr Take(const char* stage, StageOutput output, std::vector<std::string>* notes) {
  if (!output.note.empty()) notes->push_back(std::string(stage) + ": " + output.note);
  return output.cloud;
}

}  // namespace

CloudFilter::CloudFilter(const CloudFilterConfig& config) : config_(config) {
  ValidateCloudFilterConfig(config_);
}

CloudFilterResult CloudFilter::Run(const PointCloud& msg) const {
  CloudFilterResult result;
  StageClock clock;
  PclCloud::Ptr cloud = ToPcl(msg);
  clock.Lap("input", cloud->size());

  cloud = KeepDepthRange(cloud, config_.z_min, config_.z_max);
  cloud = Take("passthrough", EmptyIfOnePoint(cloud), &result.notes);
  clock.Lap("passthrough", cloud->size());

  double voxel_leaf = 0;  // 0: the cloud was not voxelised
  if (config_.voxel_enabled) {
    VoxelOutput voxels = DownsampleVoxels(cloud, config_.voxel_leaf);
    voxel_leaf = voxels.leaf;
    cloud = Take("voxel", std::move(voxels), &result.notes);
  }
  clock.Lap("voxel", cloud->size());

  if (config_.outliers_enabled)
    cloud = Take("outliers",
                 RemoveOutliers(cloud, config_.outliers_mean_k, config_.outliers_stddev_mul, voxel_leaf),
                 &result.notes);
  clock.Lap("outliers", cloud->size());

  PlaneFit plane;
  if (config_.plane_enabled)
    plane = FitPlane(cloud, config_.plane_distance, config_.plane_max_iterations,
                     config_.plane_min_inliers, config_.plane_ransac_points);
  if (!plane.note.empty()) result.notes.push_back("plane: " + plane.note);
  clock.Lap("plane", plane.inliers);

  result.cloud = FromPcl(*cloud, msg.nintensity > 0, msg);
  result.stats = clock.stats();
  result.stats.utime = msg.utime;
  result.stats.frame_id = msg.frame_id;
  result.stats.plane_found = plane.found;
  for (int i = 0; i < 3; ++i) result.stats.plane_normal[i] = plane.normal[i];
  result.stats.plane_offset = plane.offset;
  result.stats.inlier_rms = plane.inlier_rms;
  return result;
}

void SilencePclConsole() { pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS); }

}  // namespace ws
