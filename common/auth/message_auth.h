// Authentication of the messages that act on a process or decide what it
// does: commands (STEREO_COMMAND), calibrations (STEREO_CALIBRATION), the
// corners a calibration is solved from (STEREO_CORNERS) and the images
// (STEREO_IMAGES): the message types that carry an auth_t (docs/security.md).
//
// A sender with the rig key fills auth_t (sender, time, a random nonce, the
// key's id) and the MAC: keyed BLAKE2b-256 (libsodium's crypto_generichash)
// over the channel name, a NUL and the encoded message with auth.mac zeroed,
// so that every field is covered and a message cannot be moved to another
// channel. auth_t is the last field of every such type, so the encoding ends
// with auth.mac: the MAC is computed on the bytes as they travel, its last
// 32 read as zeros, with no copy of the message (a 2.4 MB image pair).
// A receiver with the key refuses what is unsigned, signed with another key,
// altered, signed more than kWindowUs before its own clock or more than a
// small skew after it, or before it started
// (its nonces start empty), or a nonce it has accepted before. Process does
// both for every such type it publishes or subscribes to; Sign() is the one
// call any other publisher needs.
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

// Whether Msg carries an auth_t (command_t, stereo_calibration_t,
// stereo_corners_t, stereo_frame_t).
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

// The MAC of a message on `channel` whose encoding is encoded[0, size): over
// the channel, a NUL and the encoding with its last 32 bytes (auth.mac) as
// zeros.
std::array<uint8_t, 32> Mac(const RigKey& key, const std::string& channel, const uint8_t* encoded, size_t size);
int64_t RandomNonce();

// The encoding of msg with `auth` in its place: msg encoded as it is, its
// auth_t tail replaced (no copy of msg).
template <class Msg>
std::vector<uint8_t> EncodeWithAuth(const Msg& msg, const widestereo::auth_t& auth) {
  const int size = msg.getEncodedSize();
  const int head = size - msg.auth._getEncodedSizeNoHash();
  const int with_auth = head + auth._getEncodedSizeNoHash();
  std::vector<uint8_t> bytes(size_t(std::max(size, with_auth)));
  if (msg.encode(bytes.data(), 0, size) < 0 || auth._encodeNoHash(bytes.data(), head, with_auth - head) < 0)
    throw std::invalid_argument("the message does not encode");
  bytes.resize(size_t(with_auth));
  return bytes;
}

// The encoding of msg signed for `channel` as `sender` at `utime`
// (microseconds since the epoch): what Process publishes.
template <class Msg>
std::vector<uint8_t> EncodeSigned(const RigKey& key, const std::string& channel, const std::string& sender,
                                  int64_t utime, const Msg& msg) {
  widestereo::auth_t auth{};
  auth.sender = sender;
  auth.utime = utime;
  auth.nonce = RandomNonce();
  auth.key_id = key.id();
  std::vector<uint8_t> bytes = EncodeWithAuth(msg, auth);
  const std::array<uint8_t, 32> mac = Mac(key, channel, bytes.data(), bytes.size());
  std::copy(mac.begin(), mac.end(), bytes.end() - mac.size());
  return bytes;
}

// Signs msg in place, as EncodeSigned does.
template <class Msg>
void Sign(const RigKey& key, const std::string& channel, const std::string& sender, int64_t utime, Msg& msg) {
  const std::vector<uint8_t> bytes = EncodeSigned(key, channel, sender, utime, msg);
  if (msg.decode(bytes.data(), 0, int(bytes.size())) < 0) throw std::logic_error("a signed message does not decode");
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

  // Throws AuthError unless msg, whose encoding is encoded[0, size) (as
  // received), is signed with this key for `channel`, at most kWindowUs
  // before now_us and max_ahead_us after it, not before not_before_us, with
  // a nonce not accepted before.
  template <class Msg>
  void Check(const std::string& channel, const Msg& msg, const uint8_t* encoded, size_t size, int64_t now_us) {
    if (msg.auth.key_id == 0) throw AuthError("refused: unsigned, and this process requires the rig key's MAC");
    constexpr size_t kMacBytes = sizeof msg.auth.mac;
    if (size < kMacBytes || !std::equal(std::begin(msg.auth.mac), std::end(msg.auth.mac), encoded + size - kMacBytes))
      throw AuthError("refused: not a message of this type as encoded");
    CheckSigned(channel, msg.auth, encoded, size, now_us);
  }
  // The same for a message not at hand as received (encoded again).
  template <class Msg>
  void Check(const std::string& channel, const Msg& msg, int64_t now_us) {
    const std::vector<uint8_t> bytes = EncodeWithAuth(msg, msg.auth);
    Check(channel, msg, bytes.data(), bytes.size(), now_us);
  }

 private:
  void CheckSigned(const std::string& channel, const widestereo::auth_t& auth, const uint8_t* encoded, size_t size,
                   int64_t now_us);

  RigKey key_;
  int64_t not_before_us_;
  int64_t max_ahead_us_;
  std::mutex mutex_;  // guards the two below
  std::deque<std::pair<int64_t, int64_t>> accepted_;  // (signing time, nonce), in order of arrival
  std::unordered_set<int64_t> nonces_;                // the nonces of accepted_
};

}  // namespace ws::auth
