// Where a command may make a process write: a new file of the one kind that
// command writes (".yaml" calibration, ".json" report, ".pcd" cloud), with a
// plain name, inside one of the folders the process was started with
// (--pcd-dir, the folder of --out or --report); never a place the sender
// chooses, never a file of another kind (a views state, a log, a recording),
// and an existing file only when the command says overwrite=1, the old one
// then kept as a backup. Every command argument that names a file goes
// through CommandOutputFile, so a peer on the bus can neither write outside
// those folders nor destroy what is in them.
#pragma once

#include <string>

namespace ws {

// What a command asks to be written: `name` in `folder`, of the kind
// `extension` (".yaml"); `overwrite`: the command said overwrite=1.
struct CommandOutput {
  std::string folder, name, extension;
  bool overwrite = false;
};

// folder/name. Throws std::invalid_argument (the command is then counted as
// rejected) when the folder is "" (the process was started without such a
// folder), when `name` is not a plain file name (empty, a '/', "..", a
// control character, longer than 200 bytes) or does not end in the
// extension, or when the file exists (a dangling symlink too) and
// `overwrite` is false.
std::string CommandOutputFile(const CommandOutput& output);

// Keeps the file at `path`, if there is one, as PATH.N.bak (N one more
// than the newest backup's): a hard link, so the old bytes survive the new
// file's rename over PATH. Only the last kKeptBackups are kept, so that a
// peer repeating `save ... overwrite=1` cannot fill the disk. Returns the
// backup's path, "" when there was no file. Throws std::runtime_error when
// no backup can be made.
inline constexpr long kKeptBackups = 10;
std::string KeepBackup(const std::string& path);

// Checks, before any work, that the file `path` given as `option` (--out,
// --report) can be written where it names: its folder ("." for a bare name)
// exists and this process may write in it. Throws std::invalid_argument
// naming the option and the folder otherwise; "" (no such file) passes.
void RequireWritableFolderOf(const std::string& option, const std::string& path);

}  // namespace ws
