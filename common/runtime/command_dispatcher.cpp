#include "runtime/command_dispatcher.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "runtime/escaped.h"

namespace ws {

std::string CommandArgs::Value(const std::string& key) const {
  for (auto arg = args.rbegin(); arg != args.rend(); ++arg)
    if (arg->key == key) return arg->value;
  return "";
}

void CommandArgs::Refuse(const Arg& arg, const std::string& why) const {
  throw std::invalid_argument("command '" + command + "': bad argument " + Quoted(arg.text) + ": " + why);
}

CommandDispatcher::CommandDispatcher(std::string process, std::vector<CommandSpec> commands)
    : process_(std::move(process)), commands_(std::move(commands)) {}

void CommandDispatcher::Dispatch(const widestereo::command_t& msg) const {
  if (!msg.target.empty() && msg.target != process_) return;
  const auto spec = std::find_if(commands_.begin(), commands_.end(),
                                 [&](const CommandSpec& c) { return c.name == msg.command; });
  if (spec == commands_.end()) {
    if (msg.target.empty()) return;  // meant for another process
    std::string known;
    for (const CommandSpec& c : commands_) known += (known.empty() ? "" : ", ") + c.usage;
    throw std::invalid_argument("unknown command '" + msg.command + "' (" + process_ + " knows: " + known + ")");
  }
  CommandArgs args{msg.command, {}};
  for (const std::string& text : msg.args) {
    const size_t eq = text.find('=');
    args.args.push_back({text, text.substr(0, eq), eq == std::string::npos ? "" : text.substr(eq + 1)});
    if (std::find(spec->keys.begin(), spec->keys.end(), args.args.back().key) == spec->keys.end())
      args.Refuse(args.args.back(), spec->keys.empty() ? "takes no arguments" : "unknown argument");
  }
  spec->run(args);
}

}  // namespace ws
