// What a faulty or hostile peer sends on a channel: random bytes, messages cut
// short, messages of another type, well-formed messages the receiver must
// refuse (sizes beyond the limits, values it cannot use), and payloads far
// larger than any real message. Every one must be rejected by the subscriber.
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "lcm_io/decode.h"

namespace ws::test {

class BadMessages {
 public:
  // `good`: an encoded message of the channel's type; `other_type`: one of
  // another type; `invalid`: one of the channel's type that decodes but that
  // the receiver must refuse (e.g. sizes beyond the limits).
  BadMessages(std::vector<uint8_t> good, std::vector<uint8_t> other_type,
              std::vector<uint8_t> invalid, uint32_t seed);

  // The next bad payload, cycling through the kinds.
  std::vector<uint8_t> Next();
  // "garbage", "truncated", "wrong type", "invalid", "oversized payload".
  static const std::vector<std::string>& Kinds();

 private:
  std::vector<uint8_t> Random(size_t size);

  std::vector<uint8_t> good_, other_type_, invalid_;
  std::mt19937 rng_;
  int next_ = 0;
};

template <class Msg>
std::vector<uint8_t> Encoded(const Msg& msg) {
  return ws::EncodeMessage(msg);
}

}  // namespace ws::test
