// Settings of the stereo-cloud filter chain and their loader.
#pragma once

#include <stdexcept>
#include <string>

namespace ws {

// A settings file or struct that is missing a field, has a field of the wrong
// type, or a value out of range. The message names the file (when there is
// one), the field and the reason.
struct ConfigError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The defaults are the example values. As a YAML file (OpenCV needs the first
// line exactly as shown; every field is required, unknown fields are errors):
//
//   %YAML:1.0
//   z_min: 0.3                  # metres; nearer points are dropped,
//   z_max: 10.0                 # farther ones too (OpenCV puts missing disparities at Z = 10000)
//   voxel_enabled: true
//   voxel_leaf: 0.01            # metres
//   outliers_enabled: true
//   outliers_mean_k: 20         # neighbours per point
//   outliers_stddev_mul: 2.0    # drop points farther from their neighbours than mean + mul * stddev
//   plane_enabled: true
//   plane_distance: 0.02        # metres; RANSAC inlier threshold
//   plane_max_iterations: 1000
//   plane_min_inliers: 100      # fewer inliers than this: no plane
//
// The depth pass-through always runs: it drops NaN and infinite points, which
// every later stage would choke on.
struct CloudFilterConfig {
  double z_min = 0.3;
  double z_max = 10.0;
  bool voxel_enabled = true;
  double voxel_leaf = 0.01;
  bool outliers_enabled = true;
  int outliers_mean_k = 20;
  double outliers_stddev_mul = 2.0;
  bool plane_enabled = true;
  double plane_distance = 0.02;
  int plane_max_iterations = 1000;
  int plane_min_inliers = 100;
};

// Throws ConfigError "field 'NAME': REASON" for the first value out of range.
void ValidateCloudFilterConfig(const CloudFilterConfig& config);

// Reads and validates a YAML file laid out as above. Throws ConfigError
// "PATH: field 'NAME': REASON" (or "PATH: REASON" when the file itself is bad).
CloudFilterConfig LoadCloudFilterConfig(const std::string& path);

}  // namespace ws
