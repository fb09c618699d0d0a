// Reading LCM log files without trusting them: their structure, and every
// intact event of a damaged one.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

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

// One event of an LCM log.
struct LcmLogEvent {
  int64_t eventnum = 0;
  int64_t timestamp = 0;
  std::string channel;
  std::vector<uint8_t> data;
};

// The intact events of a log, damaged or not, and what the damage cost.
struct LcmLogRecovery {
  std::vector<LcmLogEvent> events;  // in the order of the file
  int64_t file_bytes = 0;
  int64_t lost_bytes = 0;  // bytes in no intact event
  // Events lost: the gaps in the intact events' numbers around each damaged
  // stretch (LCM numbers events 0, 1, 2, ...; one where the numbers cannot
  // say), and one for a damaged end.
  int64_t lost_events = 0;
  std::string first_damage;  // "bad sync word at byte 22074"; "" when intact

  bool intact() const { return lost_bytes == 0; }
};

// Whether an event's data is what its channel carries (decodes as its type).
using LcmEventCheck = std::function<bool(const std::string& channel, const uint8_t* data, size_t size)>;

// Reads every intact event of `path`, so that one damaged byte costs the
// event it is in, not every event after it. An event is intact when its
// header is plausible (sync word, lengths non-negative and within the file,
// a channel of printable characters no longer than ours) and `check` accepts
// its data. Where one is not, the reader resynchronises: it moves on byte by
// byte to the next sync word that starts an intact event. Every size is
// checked before the data is touched. Throws std::runtime_error only when
// the file cannot be read.
LcmLogRecovery RecoverLcmLog(const std::string& path, const LcmEventCheck& check);

// The bytes of an LCM log of `events`, numbered from 0 as LCM numbers them.
std::string EncodeLcmLog(const std::vector<LcmLogEvent>& events);

// The path of a file:// LCM URL ("file:///tmp/x.lcmlog?speed=0" ->
// "/tmp/x.lcmlog"), or "" when the URL is not a file URL.
std::string LcmFileUrlPath(const std::string& url);
// The same file:// URL with another path ("file:///a.lcmlog?speed=0", "/b.lcmlog"
// -> "file:///b.lcmlog?speed=0").
std::string LcmFileUrlWithPath(const std::string& url, const std::string& path);

}  // namespace ws
