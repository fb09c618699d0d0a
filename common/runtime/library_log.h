// What the libraries below widestereo say through glog (Ceres Solver: a
// Levenberg-Marquardt step it retries after a failed factorisation, and
// the like) goes into the process's text log, not onto the terminal in
// glog's own format: warnings and below as detail lines of the log file,
// errors as the process's errors. glog writes no files of its own.
#pragma once

#include <memory>

#include "runtime/text_log.h"

namespace ws {

// While one lives, glog's messages go to `log` (which must outlive it).
// The first one in a process sets glog up for this; others (tests that run
// several processes' nodes at once) each receive the messages too.
class LibraryLog {
 public:
  explicit LibraryLog(TextLog& log);
  ~LibraryLog();
  LibraryLog(const LibraryLog&) = delete;
  LibraryLog& operator=(const LibraryLog&) = delete;

 private:
  class Sink;
  std::unique_ptr<Sink> sink_;
};

}  // namespace ws
