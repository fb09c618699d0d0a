// The commands a process takes on STEREO_COMMAND, declared once: each one's
// name, how a refusal lists it, the KEY=VALUE arguments it takes and what it
// does. Dispatch does what every process did by hand before:
//
//   CommandDispatcher commands("stereo-cloud", {
//       {"save", "save [path=NAME.pcd]", {"path", "overwrite"},
//        [this](const CommandArgs& args) { Save(args.Value("path")); }}});
//   ... Subscribe<widestereo::command_t>(channel::kStereoCommand,
//                                        [&](const auto& msg) { commands.Dispatch(msg); });
//
// A command for another process, or one this process does not know sent to
// every process (it is another's), is ignored. What this process refuses
// throws, so that Process counts it as rejected on STEREO_COMMAND.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "widestereo/command_t.hpp"

namespace ws {

// A command's arguments, each "KEY=VALUE" (a KEY alone has the value "").
struct CommandArgs {
  struct Arg {
    std::string text, key, value;
  };
  std::string command;
  std::vector<Arg> args;  // in the order sent

  // The value of the last KEY=VALUE given; "" when there is none.
  std::string Value(const std::string& key) const;
  // Throws std::invalid_argument("command 'CMD': bad argument 'TEXT': why").
  [[noreturn]] void Refuse(const Arg& arg, const std::string& why) const;
};

struct CommandSpec {
  std::string name;
  std::string usage;              // how a refusal of an unknown command lists it
  std::vector<std::string> keys;  // the argument keys it takes
  std::function<void(const CommandArgs&)> run;
};

class CommandDispatcher {
 public:
  CommandDispatcher(std::string process, std::vector<CommandSpec> commands);

  // Runs the command if it is for this process (target empty or this
  // process's name). Throws std::invalid_argument for a command this process
  // does not know sent to it by name ("unknown command 'X' (PROCESS knows:
  // USAGE, ...)") and for an argument of a key the command does not take;
  // and whatever the command throws.
  void Dispatch(const widestereo::command_t& msg) const;

 private:
  std::string process_;
  std::vector<CommandSpec> commands_;
};

}  // namespace ws
