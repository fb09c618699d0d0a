#include "runtime/process_cli.h"

#include <iostream>
#include <memory>

#include "runtime/yaml_config.h"

namespace ws {
namespace {

// The first option a CLI11 message names ("--rate" of "Could not convert:
// --rate = fast"), or "".
std::string OptionNamed(const std::string& message) {
  const size_t at = message.find("--");
  if (at == std::string::npos) return "";
  const size_t end = message.find_first_not_of(
      "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_", at + 2);
  return message.substr(at, end == std::string::npos ? std::string::npos : end - at);
}

// Whether `option` ("--rate") is among the arguments, alone or as --rate=X.
bool OnCommandLine(const std::string& option, int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == option || arg.rfind(option + "=", 0) == 0) return true;
  }
  return false;
}

}  // namespace

ProcessCli::ProcessCli(std::string name, std::string description)
    : app_(std::move(description), name) {
  options_.name = std::move(name);
  app_.config_formatter(std::make_shared<YamlConfig>());
  app_.allow_config_extras(CLI::config_extras_mode::error);
  app_.set_config("--config", "", "YAML file of option: value (command-line flags override it)");
  app_.add_option("--in-url", options_.in_url,
                  "LCM URL to read from (default: LCM's default, udpm multicast); "
                  "'file://LOG?speed=0' replays a log as fast as it is processed");
  app_.add_option("--out-url", options_.out_url,
                  "LCM URL to publish to (default: LCM's default); 'file://LOG?mode=w' writes a log");
  app_.add_option("--log-dir", options_.log_dir, "Folder of the text log <name>.log")
      ->capture_default_str();
  app_.add_option("--key-file", options_.key_file,
                  "The rig key (a secret only its owner may read): commands, calibrations, corners and "
                  "images are then signed, and refused unless signed with it (docs/security.md)");
  app_.add_option("--max-clock-skew", options_.max_clock_skew_s,
                  "With --key-file: seconds a signed message may be dated ahead of this host's clock")
      ->check(CLI::Range(0.0, 30.0))
      ->capture_default_str();
  app_.add_flag("--quiet", options_.quiet, "Only errors on the terminal (the log file gets all)");
}

std::optional<int> ProcessCli::Parse(int argc, char** argv) {
  try {
    app_.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app_.exit(e);  // --help
    // Name the config file where the error is in it, and say "unknown
    // option" where CLI11 says "INI".
    std::string why = e.what();
    const std::string ini = "INI was not able to parse ";
    if (why.rfind(ini, 0) == 0) why = "unknown option '" + why.substr(ini.size()) + "'";
    const CLI::Option* config = app_.get_config_ptr();
    const std::string option = OptionNamed(why);
    const bool in_config = dynamic_cast<const CLI::ConfigError*>(&e) != nullptr ||
                           (!option.empty() && !OnCommandLine(option, argc, argv));
    const std::string file = in_config && config && config->count() ? config->as<std::string>() + ": " : "";
    std::cerr << options_.name << ": " << file << why << "\nRun with --help for more information.\n";
    return e.get_exit_code();
  }
  if (auto* config = app_.get_config_ptr(); config && config->count() > 0)
    options_.config_file = config->as<std::string>();
  return std::nullopt;
}

}  // namespace ws
