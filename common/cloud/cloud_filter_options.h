// The filter chain's settings as command-line options of stereo-cloud, and
// so as keys of its flat YAML config (config/stereo-cloud.yaml).
#pragma once

#include <CLI/CLI.hpp>

#include "cloud/cloud_filter_config.h"

namespace ws {

// Adds --z-min, --z-max, --voxel, --voxel-leaf, --outliers,
// --outliers-mean-k, --outliers-stddev-mul, --plane, --plane-distance,
// --plane-max-iterations and --plane-min-inliers, each writing its field of
// `config` (whose values are the defaults shown). Switches take true/false.
// Check the parsed values with ValidateCloudFilterConfig.
void AddCloudFilterOptions(CLI::App& app, CloudFilterConfig* config);

}  // namespace ws
