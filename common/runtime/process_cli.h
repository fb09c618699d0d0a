// The command line every widestereo executable shares (DESIGN.md,
// "Command-line contract"): --help, --config FILE.yaml, --in-url, --out-url,
// --log-dir, --quiet, --key-file; each process adds its own options to app().
#pragma once

#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "runtime/process_options.h"

namespace ws {

class ProcessCli {
 public:
  ProcessCli(std::string name, std::string description);

  CLI::App& app() { return app_; }
  const ProcessOptions& options() const { return options_; }

  // Parses the config file (if any) and then the command line. Returns an
  // exit code when the process should stop now (--help: 0, bad usage: non-zero,
  // after printing why), nothing when it should run.
  std::optional<int> Parse(int argc, char** argv);

 private:
  CLI::App app_;
  ProcessOptions options_;
};

}  // namespace ws
