#include "cloud/cloud_filter_config.h"

#include <cmath>
#include <sstream>

namespace ws {
namespace {

[[noreturn]] void OptionError(const std::string& option, const std::string& reason) {
  throw ConfigError(option + ": " + reason);
}

std::string Show(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

void RequireFinite(const char* option, double value) {
  if (!std::isfinite(value)) OptionError(option, "must be a finite number, got " + Show(value));
}

void RequirePositive(const char* option, double value) {
  RequireFinite(option, value);
  if (value <= 0) OptionError(option, "must be > 0, got " + Show(value));
}

void RequireAtLeast(const char* option, int value, int minimum) {
  if (value < minimum)
    OptionError(option, "must be >= " + std::to_string(minimum) + ", got " + std::to_string(value));
}

}  // namespace

void ValidateCloudFilterConfig(const CloudFilterConfig& config) {
  RequireFinite("--z-min", config.z_min);
  RequireFinite("--z-max", config.z_max);
  if (config.z_max <= config.z_min)
    OptionError("--z-max", "must be greater than --z-min (" + Show(config.z_min) + "), got " +
                               Show(config.z_max));
  RequirePositive("--voxel-leaf", config.voxel_leaf);
  RequireAtLeast("--outliers-mean-k", config.outliers_mean_k, 1);
  RequirePositive("--outliers-stddev-mul", config.outliers_stddev_mul);
  RequirePositive("--plane-distance", config.plane_distance);
  RequireAtLeast("--plane-max-iterations", config.plane_max_iterations, 1);
  RequireAtLeast("--plane-min-inliers", config.plane_min_inliers, 3);  // a plane needs 3 points
  RequireAtLeast("--plane-ransac-points", config.plane_ransac_points, 0);
}

}  // namespace ws
