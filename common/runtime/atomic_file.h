// Files written so that a reader, a crash or a full disk never sees a part:
// the old file or the whole new one. The bytes go to a temporary file in the
// same folder, created anew (O_CREAT | O_EXCL | O_NOFOLLOW: never an existing
// file or a symlink someone planted), every write and the fsync checked, then
// renamed over the final name. rename(2) replaces a symlink at the final name
// with the file itself, so the final name is never followed either.
//
// Several files that belong together (a calibration, its model files and
// its report; an export's files) are an OutputSet: while one is open on a
// thread, WriteFileAtomically on that thread writes into it, and its files
// are put in place together when it is committed. Until then every old file
// stands, whole; a set left uncommitted (an error, an exception) removes its
// temporary files and changes nothing.
#pragma once

#include <string>
#include <vector>

namespace ws {

// Writes `bytes` to `path` atomically (or, within an OutputSet on this
// thread, into the set). On any failure the temporary file is removed, the
// file at `path` is left as it was, and std::runtime_error says what failed
// ("cannot write 'PATH': writing: No space left on device").
void WriteFileAtomically(const std::string& path, const std::string& bytes);

// Whether `path` names an existing file or symlink (a dangling one too).
bool PathExists(const std::string& path);

class OutputSet {
 public:
  OutputSet();  // collects this thread's WriteFileAtomically until Commit or destruction
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;
  ~OutputSet();  // removes the temporary files of a set not committed

  // Writes `bytes` to a temporary file beside `path`; throws as
  // WriteFileAtomically does.
  void Add(const std::string& path, const std::string& bytes);
  // Puts every file in place, in the order added; ends the collecting.
  // Throws std::runtime_error naming the file that could not be renamed.
  void Commit();

 private:
  struct Pending {
    std::string path, tmp;
  };
  std::vector<Pending> pending_;
  OutputSet* outer_;  // the set this one hides on the thread, if any
};

}  // namespace ws
