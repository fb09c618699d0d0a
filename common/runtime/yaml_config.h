// CLI11 reads a process's --config FILE.yaml through this: the file is a flat
// YAML map whose keys are the process's long option names (without "--"),
// e.g. `board: chessboard:9x6:0.025`. Sequences give multi-value options.
// Flags on the command line override the file.
#pragma once

#include <CLI/CLI.hpp>

namespace ws {

class YamlConfig : public CLI::Config {
 public:
  std::string to_config(const CLI::App* app, bool default_also, bool write_description,
                        std::string prefix) const override;
  // Throws CLI::ConfigError naming the line when the YAML does not parse,
  // and for anything but a flat map of scalars and sequences of scalars.
  std::vector<CLI::ConfigItem> from_config(std::istream& input) const override;
};

}  // namespace ws
