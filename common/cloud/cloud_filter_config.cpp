#include "cloud/cloud_filter_config.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include <opencv2/core.hpp>

#include "runtime/opencv_yaml.h"

namespace ws {
namespace {

[[noreturn]] void FieldError(const std::string& name, const std::string& reason) {
  throw ConfigError("field '" + name + "': " + reason);
}

std::string Show(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

void RequireFinite(const char* name, double value) {
  if (!std::isfinite(value)) FieldError(name, "must be a finite number, got " + Show(value));
}

void RequirePositive(const char* name, double value) {
  RequireFinite(name, value);
  if (value <= 0) FieldError(name, "must be > 0, got " + Show(value));
}

void RequireAtLeast(const char* name, int value, int minimum) {
  if (value < minimum)
    FieldError(name, "must be >= " + std::to_string(minimum) + ", got " + std::to_string(value));
}

// Reads typed fields from a YAML map and remembers which names were asked
// for, so that whatever is left over can be reported as unknown.
class FieldReader {
 public:
  explicit FieldReader(const cv::FileNode& map) : map_(map) {}

  void Read(const char* name, double* value) {
    const cv::FileNode node = Find(name);
    if (!node.isInt() && !node.isReal()) FieldError(name, "must be a number");
    *value = double(node);
  }

  void Read(const char* name, int* value) {
    const cv::FileNode node = Find(name);
    if (!node.isInt()) FieldError(name, "must be an integer");
    *value = int(node);
  }

  void Read(const char* name, bool* value) {
    const cv::FileNode node = Find(name);
    const std::string text = node.isString() ? node.string() : "";
    if (text != "true" && text != "false") FieldError(name, "must be true or false");
    *value = text == "true";
  }

  // Throws for a field that no Read asked for, or one that appears twice
  // (OpenCV keeps both and would silently use the first).
  void RejectUnknownAndRepeated() const {
    std::vector<std::string> seen;
    for (const cv::FileNode& node : map_) {
      const std::string name = node.name();
      if (std::find(known_.begin(), known_.end(), name) == known_.end())
        FieldError(name, "unknown field");
      if (std::find(seen.begin(), seen.end(), name) != seen.end())
        FieldError(name, "given more than once");
      seen.push_back(name);
    }
  }

 private:
  cv::FileNode Find(const char* name) {
    known_.emplace_back(name);
    const cv::FileNode node = map_[name];
    if (node.empty()) FieldError(name, "missing");
    return node;
  }

  const cv::FileNode map_;
  std::vector<std::string> known_;
};

cv::FileNode OpenRootMap(cv::FileStorage& storage, const std::string& path) {
  try {
    OpenOpenCvYaml(storage, path);
  } catch (const YamlFileError& e) {
    throw ConfigError(e.what());
  }
  const cv::FileNode root = storage.root();
  if (!root.isMap()) throw ConfigError("the file must be a YAML map of field: value");
  return root;
}

}  // namespace

void ValidateCloudFilterConfig(const CloudFilterConfig& config) {
  RequireFinite("z_min", config.z_min);
  if (config.z_min < 0) FieldError("z_min", "must be >= 0, got " + Show(config.z_min));
  RequireFinite("z_max", config.z_max);
  if (config.z_max <= config.z_min)
    FieldError("z_max", "must be greater than z_min (" + Show(config.z_min) + "), got " +
                            Show(config.z_max));
  RequirePositive("voxel_leaf", config.voxel_leaf);
  RequireAtLeast("outliers_mean_k", config.outliers_mean_k, 1);
  RequirePositive("outliers_stddev_mul", config.outliers_stddev_mul);
  RequirePositive("plane_distance", config.plane_distance);
  RequireAtLeast("plane_max_iterations", config.plane_max_iterations, 1);
  RequireAtLeast("plane_min_inliers", config.plane_min_inliers, 3);  // a plane needs 3 points
}

CloudFilterConfig LoadCloudFilterConfig(const std::string& path) {
  try {
    cv::FileStorage storage;
    FieldReader fields(OpenRootMap(storage, path));
    CloudFilterConfig config;
    fields.Read("z_min", &config.z_min);
    fields.Read("z_max", &config.z_max);
    fields.Read("voxel_enabled", &config.voxel_enabled);
    fields.Read("voxel_leaf", &config.voxel_leaf);
    fields.Read("outliers_enabled", &config.outliers_enabled);
    fields.Read("outliers_mean_k", &config.outliers_mean_k);
    fields.Read("outliers_stddev_mul", &config.outliers_stddev_mul);
    fields.Read("plane_enabled", &config.plane_enabled);
    fields.Read("plane_distance", &config.plane_distance);
    fields.Read("plane_max_iterations", &config.plane_max_iterations);
    fields.Read("plane_min_inliers", &config.plane_min_inliers);
    fields.RejectUnknownAndRepeated();
    ValidateCloudFilterConfig(config);
    return config;
  } catch (const ConfigError& e) {
    throw ConfigError(path + ": " + e.what());
  }
}

}  // namespace ws
