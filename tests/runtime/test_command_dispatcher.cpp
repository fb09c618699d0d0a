// The command dispatcher (runtime/command_dispatcher.h): the target filter,
// the refusal of what a process does not take, and KEY=VALUE arguments.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "runtime/command_dispatcher.h"

namespace {

widestereo::command_t Command(const std::string& command, const std::string& target,
                              const std::vector<std::string>& args = {}) {
  widestereo::command_t msg{};
  msg.command = command;
  msg.target = target;
  msg.args = args;
  msg.nargs = int32_t(args.size());
  return msg;
}

std::string Refusal(const ws::CommandDispatcher& commands, const widestereo::command_t& msg) {
  try {
    commands.Dispatch(msg);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

struct Saves {
  std::vector<std::string> paths;
  int refines = 0;
  ws::CommandDispatcher commands{"stereo-test",
                                 {{"save", "save [path=NAME]", {"path", "overwrite"},
                                   [this](const ws::CommandArgs& args) { paths.push_back(args.Value("path")); }},
                                  {"refine", "refine", {}, [this](const ws::CommandArgs&) { ++refines; }}}};
};

TEST(CommandDispatcher, RunsWhatIsForThisProcessAndIgnoresWhatIsForAnother) {
  Saves s;
  s.commands.Dispatch(Command("save", "", {"path=a"}));
  s.commands.Dispatch(Command("save", "stereo-test", {"path=b", "overwrite=1", "path=c"}));
  s.commands.Dispatch(Command("save", "stereo-other", {"path=d"}));
  s.commands.Dispatch(Command("flush", ""));  // another process's command
  s.commands.Dispatch(Command("refine", "stereo-test"));
  EXPECT_EQ(s.paths, (std::vector<std::string>{"a", "c"}));  // the last path= given
  EXPECT_EQ(s.refines, 1);
}

TEST(CommandDispatcher, RefusesWhatThisProcessDoesNotTakeSayingWhatItDoes) {
  Saves s;
  EXPECT_EQ(Refusal(s.commands, Command("flush", "stereo-test")),
            "unknown command 'flush' (stereo-test knows: save [path=NAME], refine)");
  EXPECT_EQ(Refusal(s.commands, Command("save", "", {"path=a", "colour=red"})),
            "command 'save': bad argument 'colour=red': unknown argument");
  EXPECT_EQ(Refusal(s.commands, Command("refine", "", {"now"})),
            "command 'refine': bad argument 'now': takes no arguments");
  EXPECT_TRUE(s.paths.empty());
  EXPECT_EQ(s.refines, 0);
}

}  // namespace
