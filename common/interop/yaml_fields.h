// Checked reading of another tool's plain YAML file (Kalibr's camchain,
// ROS's camera_info) with yaml-cpp: the file is bounded and its layout
// checked before it is parsed (runtime/bounded_file.h, opencv_yaml.h), and
// every refusal is a CalibrationFileError "FILE: FIELD: REASON".
#pragma once

#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace ws {

class YamlFields {
 public:
  explicit YamlFields(std::string path) : path_(std::move(path)) {}

  // The file's top node; max_bytes: the largest such a file can be.
  YAML::Node Load(size_t max_bytes) const;

  [[noreturn]] void Fail(const std::string& field, const std::string& reason) const;
  // `count` finite numbers; any count from 0 to max_count with count < 0.
  std::vector<double> Numbers(const YAML::Node& node, const std::string& field, int count,
                              size_t max_count = 0) const;
  std::string Text(const YAML::Node& node, const std::string& field) const;
  // A whole number from min to max.
  int Whole(const YAML::Node& node, const std::string& field, int min, int max) const;

 private:
  std::string path_;
};

}  // namespace ws
