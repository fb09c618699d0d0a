// Files written so that a reader, a crash or a full disk never sees a part:
// the old file or the whole new one. The bytes go to a temporary file in the
// same folder, created anew (O_CREAT | O_EXCL | O_NOFOLLOW: never an existing
// file or a symlink someone planted), every write and the fsync checked, then
// renamed over the final name. rename(2) replaces a symlink at the final name
// with the file itself, so the final name is never followed either.
#pragma once

#include <string>

namespace ws {

// Writes `bytes` to `path` atomically. On any failure the temporary file is
// removed, the file at `path` is left as it was, and std::runtime_error says
// what failed ("cannot write 'PATH': writing: No space left on device").
void WriteFileAtomically(const std::string& path, const std::string& bytes);

// Whether `path` names an existing file or symlink (a dangling one too).
bool PathExists(const std::string& path);

}  // namespace ws
