// Settings of the stereo-cloud filter chain. stereo-cloud takes each as a
// command-line option (cloud_filter_options.h), so also as a key of its flat
// YAML config (config/stereo-cloud.yaml); the option names are given below.
#pragma once

#include <stdexcept>
#include <string>

namespace ws {

// A value out of range. The message names the option and the reason.
struct ConfigError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The depth pass-through always runs: it drops NaN and infinite points, which
// every later stage would choke on.
struct CloudFilterConfig {
  double z_min = 0.3;                // --z-min, metres: nearer points are dropped (negative: keeps
                                     //   points behind the image plane, a lat-lon cloud past 90 degrees),
  double z_max = 10.0;               // --z-max, and farther ones (OpenCV puts missing disparities at Z = 10000)
  bool voxel_enabled = true;         // --voxel
  double voxel_leaf = 0.01;          // --voxel-leaf, metres
  bool outliers_enabled = true;      // --outliers
  int outliers_mean_k = 20;          // --outliers-mean-k, neighbours per point
  double outliers_stddev_mul = 2.0;  // --outliers-stddev-mul: drop points farther from their
                                     //   neighbours than mean + mul * stddev
  bool plane_enabled = true;         // --plane
  double plane_distance = 0.02;      // --plane-distance, metres: RANSAC inlier threshold
  int plane_max_iterations = 1000;   // --plane-max-iterations
  int plane_min_inliers = 100;       // --plane-min-inliers: fewer inliers than this, no plane
  int plane_ransac_points = 20000;   // --plane-ransac-points: RANSAC on at most this many (0: all)
};

// Throws ConfigError "--NAME: REASON" for the first value out of range.
void ValidateCloudFilterConfig(const CloudFilterConfig& config);

}  // namespace ws
