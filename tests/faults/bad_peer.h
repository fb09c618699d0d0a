// The bad peer of the fault tests: it floods the channels a process reads
// with bad messages (bad_messages.h) between good ones, over udpm, and checks
// the process's counters; and the clean run its output is compared with.
#pragma once

#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

#include "auth/message_auth.h"
#include "lcm_io/decode.h"
#include "runtime/wall_clock.h"

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

// Each payload of a Msg with its auth_t cleared, as a process without a key
// sends it: what a keyed run is compared with a clean run on.
template <class Msg>
std::vector<std::vector<uint8_t>> WithoutAuth(const std::vector<std::vector<uint8_t>>& payloads) {
  std::vector<std::vector<uint8_t>> out;
  for (const auto& p : payloads)
    out.push_back(ws::auth::EncodeWithAuth(ws::DecodeMessage<Msg>(p.data(), int(p.size())), widestereo::auth_t{}));
  return out;
}

// Sends kBadPerGoodFrame bad messages on each channel, interleaved and paced.
void Flood(BusWatch& bus, const std::vector<BadChannel*>& channels);

// The bad-peer tests run without a rig key and with one: then the process
// gets --key-file and the test signs the good messages (commands,
// calibrations, corners, images).
class BadPeer : public ::testing::TestWithParam<bool> {
 protected:
  bool keyed() const { return GetParam(); }
  // The key's arguments for the process (none without a key); makes the key in `dir`.
  std::vector<std::string> KeyArgs(const std::string& dir);
  // msg as the test sends it on `channel`: signed when there is a key.
  template <class Msg>
  Msg AsSent(const std::string& channel, Msg msg) const {
    if (key_) ws::auth::Sign(*key_, channel, "bad-peer test", ws::WallMicros(), msg);
    return msg;
  }

 private:
  std::optional<ws::auth::RigKey> key_;
};

// Every message the process received on the channel was one of the `good`
// ones or is counted as rejected; most of what was sent arrived (udpm on one
// host; LCM drops silently what does not fit its queue).
void ExpectRejectedAllBad(const BusWatch& bus, const BadChannel& bad, int good);

}  // namespace ws::test
