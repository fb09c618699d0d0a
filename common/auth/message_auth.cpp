#include "auth/message_auth.h"

#include <sodium.h>

#include <cstdio>

namespace ws::auth {
namespace {

std::string Seconds(int64_t us) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f s", double(us) * 1e-6);
  return text;
}

}  // namespace

std::array<uint8_t, 32> Mac(const RigKey& key, const std::string& channel, const uint8_t* encoded, size_t size) {
  static_assert(crypto_generichash_blake2b_KEYBYTES_MIN <= 32 && crypto_generichash_blake2b_KEYBYTES_MAX >= 32);
  constexpr size_t kMacBytes = 32;
  const size_t head = size < kMacBytes ? 0 : size - kMacBytes;
  const uint8_t zeros[kMacBytes] = {};
  crypto_generichash_blake2b_state state;
  crypto_generichash_blake2b_init(&state, key.mac_key().data(), key.mac_key().size(), kMacBytes);
  crypto_generichash_blake2b_update(&state, reinterpret_cast<const uint8_t*>(channel.c_str()), channel.size() + 1);
  crypto_generichash_blake2b_update(&state, encoded, head);
  crypto_generichash_blake2b_update(&state, zeros, size - head);
  std::array<uint8_t, 32> mac;
  crypto_generichash_blake2b_final(&state, mac.data(), mac.size());
  return mac;
}

int64_t RandomNonce() {
  int64_t nonce;
  randombytes_buf(&nonce, sizeof nonce);
  return nonce;
}

void AuthCheck::CheckSigned(const std::string& channel, const widestereo::auth_t& auth, const uint8_t* encoded,
                            size_t size, int64_t now_us) {
  if (auth.key_id != key_.id())
    throw AuthError("refused: signed with another rig key (key id " + KeyIdText(auth.key_id) + ", this rig's is " +
                    key_.IdText() + ")");
  const std::array<uint8_t, 32> mac = Mac(key_, channel, encoded, size);
  if (crypto_verify_32(mac.data(), auth.mac) != 0)
    throw AuthError("refused: its MAC does not match (changed after signing, or forged)");
  const int64_t age = now_us - auth.utime;
  if (age > kWindowUs)
    throw AuthError("refused: signed " + Seconds(age) + " before this process's clock, outside the " +
                    Seconds(kWindowUs) + " window (a replay, or clocks apart)");
  if (age < -max_ahead_us_)
    throw AuthError("refused: dated " + Seconds(-age) + " after this process's clock, more than the " +
                    Seconds(max_ahead_us_) + " allowed (clocks apart: synchronise them, or --max-clock-skew)");
  if (auth.utime < not_before_us_)
    throw AuthError("refused: signed " + Seconds(not_before_us_ - auth.utime) +
                    " before this process started (a replay, or clocks apart)");
  std::lock_guard<std::mutex> lock(mutex_);
  while (!accepted_.empty() && accepted_.front().first < now_us - kWindowUs) {
    nonces_.erase(accepted_.front().second);
    accepted_.pop_front();
  }
  if (!nonces_.insert(auth.nonce).second)
    throw AuthError("refused: replayed (nonce " + std::to_string(auth.nonce) + " from '" + auth.sender +
                    "' was accepted before)");
  accepted_.emplace_back(auth.utime, auth.nonce);
}

}  // namespace ws::auth
