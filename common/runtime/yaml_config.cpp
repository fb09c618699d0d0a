#include "runtime/yaml_config.h"

#include <sstream>

#include <yaml-cpp/yaml.h>

namespace ws {
namespace {

std::string Where(const YAML::Node& node) {
  return "line " + std::to_string(node.Mark().line + 1);
}

std::string ScalarText(const YAML::Node& node, const std::string& key) {
  if (!node.IsScalar())
    throw CLI::ConfigError("config key '" + key + "' (" + Where(node) +
                               ") must be a scalar or a list of scalars");
  return node.Scalar();
}

}  // namespace

std::string YamlConfig::to_config(const CLI::App* app, bool default_also, bool, std::string) const {
  YAML::Emitter out;
  out << YAML::BeginMap;
  for (const CLI::Option* opt : app->get_options()) {
    if (opt->get_lnames().empty() || !opt->get_configurable()) continue;
    const std::string& name = opt->get_lnames().front();
    if (name == "help" || name == "config") continue;
    std::vector<std::string> values = opt->reduced_results();
    if (values.empty() && default_also && !opt->get_default_str().empty())
      values = {opt->get_default_str()};
    if (values.empty()) continue;
    out << YAML::Key << name << YAML::Value;
    if (values.size() == 1)
      out << values.front();
    else
      out << YAML::Flow << values;
  }
  out << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

std::vector<CLI::ConfigItem> YamlConfig::from_config(std::istream& input) const {
  YAML::Node root;
  try {
    root = YAML::Load(input);
  } catch (const YAML::Exception& e) {
    throw CLI::ConfigError("config is not valid YAML: " + std::string(e.what()));
  }
  std::vector<CLI::ConfigItem> items;
  if (root.IsNull()) return items;
  if (!root.IsMap()) throw CLI::ConfigError("config must be a YAML map of option: value");
  for (const auto& entry : root) {
    CLI::ConfigItem item;
    item.name = entry.first.as<std::string>();
    if (entry.second.IsSequence()) {
      for (const auto& element : entry.second) item.inputs.push_back(ScalarText(element, item.name));
    } else {
      item.inputs.push_back(ScalarText(entry.second, item.name));
    }
    items.push_back(std::move(item));
  }
  return items;
}

}  // namespace ws
