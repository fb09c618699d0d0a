// Reading the structure of an LCM log file without trusting it.
#pragma once

#include <cstdint>
#include <string>

namespace ws {

// What a scan of an LCM log found: the complete events at its start, and
// where (if anywhere) the file stops being a valid log.
struct LcmLogScan {
  int64_t events = 0;
  int64_t valid_bytes = 0;  // bytes of complete, well-formed events
  int64_t file_bytes = 0;
  std::string problem;      // empty when the whole file is complete events

  bool complete() const { return problem.empty(); }
};

// Walks the event headers (sync word, event number, timestamp, channel
// length, data length), checking every size against the file before seeking
// past it. Throws std::runtime_error only when the file cannot be opened.
LcmLogScan ScanLcmLog(const std::string& path);

// The path of a file:// LCM URL ("file:///tmp/x.lcmlog?speed=0" ->
// "/tmp/x.lcmlog"), or "" when the URL is not a file URL.
std::string LcmFileUrlPath(const std::string& url);

}  // namespace ws
