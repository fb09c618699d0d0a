// The stereo-cloud filter chain: depth pass-through, voxel grid, statistical
// outlier removal and RANSAC plane fit, with per-stage point counts and times.
#pragma once

#include <string>
#include <vector>

#include "cloud/cloud_filter_config.h"
#include "widestereo/cloud_stats_t.hpp"
#include "lcm_io/point_cloud.h"

namespace ws {

struct CloudFilterResult {
  // The cloud after outlier removal, with the input's utime, frame_id and
  // frame, and intensity when the input had it.
  PointCloud cloud;
  // Stages "input", "passthrough", "voxel", "outliers", "plane" (always all
  // five; a disabled stage passes its input on): points after each (for
  // "plane", its inliers) and wall time in each. The plane's normal faces the
  // camera, so plane_offset is the camera's distance to it.
  widestereo::cloud_stats_t stats;
  // One line per stage that did not run as configured, e.g. "voxel: leaf
  // coarsened from ...", "plane: RANSAC found no plane ...".
  std::vector<std::string> notes;
};

class CloudFilter {
 public:
  // Throws ConfigError for an invalid config.
  explicit CloudFilter(const CloudFilterConfig& config);

  // Throws DecodeError when the message's counts disagree with its arrays
  // (ValidatePointCloud); any cloud that passes, however degenerate, gives a
  // result: empty when no point survives the pass-through (empty, all NaN,
  // all out of range) or all points are one point, with a note saying so;
  // without a plane for collinear points.
  CloudFilterResult Run(const PointCloud& msg) const;

  const CloudFilterConfig& config() const { return config_; }

 private:
  CloudFilterConfig config_;
};

// PCL prints its own warnings and errors on stderr for the degenerate clouds
// the chain handles and explains in its notes (RANSAC on collinear points:
// one line per try, thousands per cloud). Processes call this once to keep
// the terminal for their own log.
void SilencePclConsole();

}  // namespace ws
