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
  // Whether LCM's own file reader (1.3.1) delivers exactly the complete
  // events. It takes an event only when a sync word or the end of the file
  // follows it, so where the damage does not start with a sync word it drops
  // the last complete event; it accepts channel names up to 999 bytes, so
  // past a name longer than ours it reads on.
  bool lcm_replays_exactly = true;

  bool complete() const { return problem.empty(); }
};

// Walks the event headers (sync word, event number, timestamp, channel
// length, data length), checking every size against the file before seeking
// past it. Throws std::runtime_error only when the file cannot be opened.
LcmLogScan ScanLcmLog(const std::string& path);

// Writes the scan's complete events (the first scan.valid_bytes of `path`)
// to `copy`. Throws std::runtime_error naming the file that fails.
void CopyCompleteEvents(const std::string& path, const LcmLogScan& scan, const std::string& copy);

// The path of a file:// LCM URL ("file:///tmp/x.lcmlog?speed=0" ->
// "/tmp/x.lcmlog"), or "" when the URL is not a file URL.
std::string LcmFileUrlPath(const std::string& url);
// The same file:// URL with another path ("file:///a.lcmlog?speed=0", "/b.lcmlog"
// -> "file:///b.lcmlog?speed=0").
std::string LcmFileUrlWithPath(const std::string& url, const std::string& path);

}  // namespace ws
