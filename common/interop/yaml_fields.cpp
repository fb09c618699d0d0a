#include "interop/yaml_fields.h"

#include <cmath>

#include "rig/rig_file.h"
#include "runtime/bounded_file.h"
#include "runtime/opencv_yaml.h"

namespace ws {

YAML::Node YamlFields::Load(size_t max_bytes) const {
  std::string text;
  try {
    text = ReadBoundedFile(path_, max_bytes);
  } catch (const BoundedFileError& e) {
    Fail("(file)", e.what());
  }
  try {
    CheckOpenCvYamlLayout(text);  // no nesting deep enough to exhaust the stack
    return YAML::Load(text);
  } catch (const std::exception& e) {
    Fail("(file)", std::string("not YAML: ") + e.what());
  }
}

void YamlFields::Fail(const std::string& field, const std::string& reason) const {
  throw CalibrationFileError(path_ + ": " + field + ": " + reason);
}

std::vector<double> YamlFields::Numbers(const YAML::Node& node, const std::string& field, int count,
                                        size_t max_count) const {
  const std::string what = count >= 0 ? "a list of " + std::to_string(count) + " numbers"
                                      : "a list of at most " + std::to_string(max_count) + " numbers";
  if (!node || !node.IsSequence() || (count >= 0 ? node.size() != size_t(count) : node.size() > max_count))
    Fail(field, "missing or not " + what);
  std::vector<double> out;
  for (const YAML::Node& item : node) {
    double value = NAN;
    if (!item.IsScalar() || !YAML::convert<double>::decode(item, value) || !std::isfinite(value))
      Fail(field, "not a list of finite numbers");
    out.push_back(value);
  }
  return out;
}

std::string YamlFields::Text(const YAML::Node& node, const std::string& field) const {
  if (!node || !node.IsScalar()) Fail(field, "missing or not a string");
  return node.as<std::string>();
}

int YamlFields::Whole(const YAML::Node& node, const std::string& field, int min, int max) const {
  double value = NAN;
  if (!node || !node.IsScalar() || !YAML::convert<double>::decode(node, value) || !(value >= min && value <= max) ||
      value != std::floor(value))
    Fail(field, "missing or not a whole number from " + std::to_string(min) + " to " + std::to_string(max));
  return int(value);
}

}  // namespace ws
