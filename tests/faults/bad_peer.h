// The bad peer of the fault tests: it floods the channels a process reads
// with bad messages (bad_messages.h) between good ones, over udpm, and checks
// the process's counters; and the clean run its output is compared with.
#pragma once

#include <string>
#include <vector>

#include "bad_messages.h"
#include "bus_watch.h"
#include "test_support.h"

namespace ws::test {

constexpr int kBadPerGoodFrame = 60;
constexpr double kBadSpacingS = 0.004;  // 250 bad messages a second per channel

// The payloads `argv` publishes on `channel` replaying `in` from a log in DIR.
std::vector<std::vector<uint8_t>> CleanRun(const std::string& dir, const std::vector<LogEvent>& in,
                                           std::vector<std::string> argv, const std::string& channel);

// A channel under fire: what is sent on it, and how many.
struct BadChannel {
  std::string channel;
  BadMessages messages;
  int sent = 0;
};

// Sends kBadPerGoodFrame bad messages on each channel, interleaved and paced.
void Flood(BusWatch& bus, const std::vector<BadChannel*>& channels);

// Every message the process received on the channel was one of the `good`
// ones or is counted as rejected; most of what was sent arrived (udpm on one
// host; LCM drops silently what does not fit its queue).
void ExpectRejectedAllBad(const BusWatch& bus, const BadChannel& bad, int good);

}  // namespace ws::test
