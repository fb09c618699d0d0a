// Authentication of the messages that act on a process: commands
// (STEREO_COMMAND) and calibrations (STEREO_CALIBRATION), the message types
// that carry an auth_t (docs/security.md).
//
// A sender with the rig key fills auth_t (sender, time, a random nonce, the
// key's id) and the MAC: HMAC-SHA512-256 (libsodium's crypto_auth) over the
// channel name, a NUL and the encoded message with auth.mac zeroed, so that
// every field is covered and a message cannot be moved to another channel.
// A receiver with the key refuses what is unsigned, signed with another key,
// altered, signed more than kWindowUs before its own clock or more than a
// small skew after it, or before it started
// (its nonces start empty), or a nonce it has accepted before. Process does both for every such type it publishes or
// subscribes to; Sign() is the one call any other publisher needs.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <deque>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <unordered_set>
#include <vector>

#include "auth/rig_key.h"
#include "widestereo/auth_t.hpp"

namespace ws::auth {

// A message refused by AuthCheck; what() says why.
struct AuthError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Whether Msg carries an auth_t (command_t, stereo_calibration_t).
template <class Msg, class = void>
struct IsAuthenticated : std::false_type {};
template <class Msg>
struct IsAuthenticated<Msg, std::void_t<decltype(std::declval<Msg>().auth)>> : std::true_type {};

// How long after its signing a message is still accepted (its nonce kept
// for as long), and by default how far ahead of the receiver's clock it may
// be dated: a small skew, so that a message from a sender whose clock runs
// fast cannot be replayed to a process started after it was sent.
constexpr int64_t kWindowUs = 30'000'000;
constexpr int64_t kMaxAheadUs = 2'000'000;

// The MAC of a message on `channel` whose encoding, auth.mac zeroed, is `encoded`.
std::array<uint8_t, 32> Mac(const RigKey& key, const std::string& channel, const std::vector<uint8_t>& encoded);
int64_t RandomNonce();

// The encoding of msg with auth.mac zeroed: what the MAC covers.
template <class Msg>
std::vector<uint8_t> MacInput(Msg msg) {
  std::fill(std::begin(msg.auth.mac), std::end(msg.auth.mac), uint8_t(0));
  std::vector<uint8_t> bytes(size_t(msg.getEncodedSize()));
  msg.encode(bytes.data(), 0, int(bytes.size()));
  return bytes;
}

// Signs msg for `channel` as `sender` at `utime` (microseconds since the epoch).
template <class Msg>
void Sign(const RigKey& key, const std::string& channel, const std::string& sender, int64_t utime, Msg& msg) {
  msg.auth.sender = sender;
  msg.auth.utime = utime;
  msg.auth.nonce = RandomNonce();
  msg.auth.key_id = key.id();
  const std::array<uint8_t, 32> mac = Mac(key, channel, MacInput(msg));
  std::copy(mac.begin(), mac.end(), msg.auth.mac);
}

// What a process without a key sends: every auth_t field zero or empty.
template <class Msg>
void ClearAuth(Msg& msg) {
  msg.auth = widestereo::auth_t{};
}

// The receiving side: the key, and the nonces accepted within the window.
// Thread-safe.
class AuthCheck {
 public:
  // `not_before_us`: the receiver's start; what was signed before it could
  // have been accepted by an earlier run, whose nonces this one does not know.
  explicit AuthCheck(RigKey key, int64_t not_before_us = std::numeric_limits<int64_t>::min(),
                     int64_t max_ahead_us = kMaxAheadUs)
      : key_(std::move(key)), not_before_us_(not_before_us), max_ahead_us_(max_ahead_us) {}
  const RigKey& key() const { return key_; }

  // Throws AuthError unless msg is signed with this key for `channel`, at
  // most kWindowUs before now_us and max_ahead_us after it, not before
  // not_before_us, with a nonce not accepted before.
  template <class Msg>
  void Check(const std::string& channel, const Msg& msg, int64_t now_us) {
    if (msg.auth.key_id == 0) throw AuthError("refused: unsigned, and this process requires the rig key's MAC");
    CheckSigned(channel, msg.auth, MacInput(msg), now_us);
  }

 private:
  void CheckSigned(const std::string& channel, const widestereo::auth_t& auth, const std::vector<uint8_t>& mac_input,
                   int64_t now_us);

  RigKey key_;
  int64_t not_before_us_;
  int64_t max_ahead_us_;
  std::mutex mutex_;  // guards the two below
  std::deque<std::pair<int64_t, int64_t>> accepted_;  // (signing time, nonce), in order of arrival
  std::unordered_set<int64_t> nonces_;                // the nonces of accepted_
};

}  // namespace ws::auth
