// Where a command may make a process write: a plain file name inside one of
// the folders the process was started with (--pcd-dir, the folder of --out or
// --report), never a place the sender chooses. Every command argument that
// names a file goes through FileInFolder, so a peer on the bus cannot write
// outside those folders.
#pragma once

#include <string>

namespace ws {

// folder/name. Throws std::invalid_argument (the command is then counted as
// rejected) when `name` is empty, absolute, holds a '/' or a "..", or when
// `folder` is "" (the process was started without such a folder).
std::string FileInFolder(const std::string& folder, const std::string& name);

// Checks, before any work, that the file `path` given as `option` (--out,
// --report) can be written where it names: its folder ("." for a bare name)
// exists and this process may write in it. Throws std::invalid_argument
// naming the option and the folder otherwise; "" (no such file) passes.
void RequireWritableFolderOf(const std::string& option, const std::string& path);

}  // namespace ws
