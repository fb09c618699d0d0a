// The rig key: a secret shared by every process of one rig (--key-file), from
// which the MACs of commands, calibrations, corners and images are made
// (message_auth.h).
#pragma once

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace ws::auth {

struct KeyFileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class RigKey {
 public:
  static constexpr size_t kMinSecretBytes = 32;

  // Reads the secret from a file that only its owner may read or write (mode
  // 0600 or 0400), of at least kMinSecretBytes bytes. Throws KeyFileError
  // naming the file and the reason otherwise.
  static RigKey FromFile(const std::string& path);
  // The key of a secret (at least kMinSecretBytes bytes; KeyFileError else).
  static RigKey FromSecret(const std::string& secret);

  // The 32-byte MAC key (keyed BLAKE2b-256, message_auth.h): BLAKE2b-256 of
  // the secret.
  const std::array<uint8_t, 32>& mac_key() const { return mac_key_; }
  // Names the key in messages and errors without revealing it (never 0).
  int64_t id() const { return id_; }
  // The id as 16 hex digits.
  std::string IdText() const;

 private:
  RigKey() = default;

  std::array<uint8_t, 32> mac_key_{};
  int64_t id_ = 0;
};

// "0123456789abcdef" for a key id (also for ids read from messages).
std::string KeyIdText(int64_t id);

}  // namespace ws::auth
