// stereo-command: sends one command on STEREO_COMMAND, e.g.
//   stereo-command solve                      (stereo-calibrate: solve now)
//   stereo-command save --target stereo-cloud (write the newest filtered cloud as PCD)
//   stereo-command reset / restore            (stereo-calibrate: archive the views / bring them back)
//   stereo-command remove --arg frame=7       (stereo-calibrate: take the view of frame 7 out)
//   stereo-command refine --target stereo-health (repair the extrinsics from the live matches)
// With --key-file the command is signed with the rig key (docs/security.md).
#include <cstdio>

#include "lcm_io/channels.h"
#include "runtime/process.h"
#include "runtime/process_cli.h"
#include "widestereo/command_t.hpp"

int main(int argc, char** argv) {
  ws::ProcessCli cli("stereo-command",
                     "Sends one command (solve, reset, restore, remove, save, refine, ...) on STEREO_COMMAND to one process or "
                     "to all; signed with the rig key when given --key-file.");
  widestereo::command_t command{};
  auto& app = cli.app();
  app.add_option("command", command.command, "solve | reset | restore | remove | save | refine | ... (what the target understands)")->required();
  app.add_option("--target", command.target, "Process name (stereo-calibrate, stereo-cloud, stereo-health); default: every process");
  app.add_option("--arg", command.args, "KEY=VALUE for the command (repeatable); a file is a plain name in the target's output folder");
  if (auto rc = cli.Parse(argc, argv)) return *rc;

  try {
    ws::Process process(cli.options());
    command.nargs = int32_t(command.args.size());
    command.utime = process.Now();
    process.Publish(ws::channel::kStereoCommand, command);
    process.log().Info("sent '" + command.command + "' to " + (command.target.empty() ? "every process" : command.target));
    return process.Finish();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "stereo-command: %s\n", e.what());
    return 1;
  }
}
