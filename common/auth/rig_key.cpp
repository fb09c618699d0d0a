#include "auth/rig_key.h"

#include <sodium.h>
#include <sys/stat.h>

#include <cstdio>
#include <fstream>
#include <iterator>

namespace ws::auth {
namespace {

constexpr char kIdContext[] = "widestereo rig key id";

void InitSodium() {
  if (sodium_init() < 0) throw std::runtime_error("libsodium cannot be initialised");
}

}  // namespace

RigKey RigKey::FromFile(const std::string& path) {
  struct stat info {};
  if (stat(path.c_str(), &info) != 0) throw KeyFileError("--key-file " + path + ": cannot be read");
  if (!S_ISREG(info.st_mode)) throw KeyFileError("--key-file " + path + ": not a regular file");
  if ((info.st_mode & 077) != 0) {
    char mode[8];
    std::snprintf(mode, sizeof mode, "%04o", unsigned(info.st_mode & 07777));
    throw KeyFileError("--key-file " + path + ": mode " + mode +
                       " lets others read or change it; only its owner may (chmod 600 " + path + ")");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw KeyFileError("--key-file " + path + ": cannot be read");
  const std::string secret((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  try {
    return FromSecret(secret);
  } catch (const KeyFileError& e) {
    throw KeyFileError("--key-file " + path + ": " + e.what());
  }
}

RigKey RigKey::FromSecret(const std::string& secret) {
  if (secret.size() < kMinSecretBytes)
    throw KeyFileError("a rig key needs at least " + std::to_string(kMinSecretBytes) + " bytes of secret, this has " +
                       std::to_string(secret.size()) + " (make one: head -c 32 /dev/urandom > FILE)");
  InitSodium();
  RigKey key;
  crypto_generichash(key.mac_key_.data(), key.mac_key_.size(), reinterpret_cast<const uint8_t*>(secret.data()),
                     secret.size(), nullptr, 0);
  uint8_t id[8];
  crypto_generichash(id, sizeof id, reinterpret_cast<const uint8_t*>(kIdContext), sizeof kIdContext - 1,
                     key.mac_key_.data(), key.mac_key_.size());
  for (uint8_t byte : id) key.id_ = int64_t(uint64_t(key.id_) << 8 | byte);
  if (key.id_ == 0) key.id_ = 1;  // 0 means unsigned
  return key;
}

std::string RigKey::IdText() const { return KeyIdText(id_); }

std::string KeyIdText(int64_t id) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", (unsigned long long)id);
  return text;
}

}  // namespace ws::auth
