#include "bad_messages.h"

namespace ws::test {

namespace {
constexpr size_t kOversizedBytes = 1 << 20;  // larger than any frame these tests send
constexpr size_t kFingerprintBytes = 8;      // LCM's type hash starts every message
}  // namespace

BadMessages::BadMessages(std::vector<uint8_t> good, std::vector<uint8_t> other_type,
                         std::vector<uint8_t> invalid, uint32_t seed)
    : good_(std::move(good)), other_type_(std::move(other_type)), invalid_(std::move(invalid)),
      rng_(seed) {}

const std::vector<std::string>& BadMessages::Kinds() {
  static const std::vector<std::string> kinds = {"garbage", "truncated", "wrong type", "invalid",
                                                 "oversized payload"};
  return kinds;
}

std::vector<uint8_t> BadMessages::Random(size_t size) {
  std::vector<uint8_t> bytes(size);
  for (auto& b : bytes) b = uint8_t(rng_());
  return bytes;
}

std::vector<uint8_t> BadMessages::Next() {
  const int kind = next_++ % int(Kinds().size());
  switch (kind) {
    case 0:
      return Random(1 + rng_() % 4096);
    case 1: {
      // The right fingerprint, then the message cut anywhere before its end.
      const size_t cut = kFingerprintBytes + rng_() % (good_.size() - kFingerprintBytes);
      return std::vector<uint8_t>(good_.begin(), good_.begin() + long(cut));
    }
    case 2:
      return other_type_;
    case 3:
      return invalid_;
    default: {
      std::vector<uint8_t> bytes(good_.begin(), good_.begin() + kFingerprintBytes);
      const auto tail = Random(kOversizedBytes);
      bytes.insert(bytes.end(), tail.begin(), tail.end());
      return bytes;
    }
  }
}

}  // namespace ws::test
