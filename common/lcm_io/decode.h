// Decoding LCM payloads into typed messages, rejecting anything malformed.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "lcm_io/image_codec.h"  // DecodeError
#include "lcm_io/validate.h"

namespace ws {

// Decodes `size` bytes as a Msg and validates it (lcm_io/validate.h). A
// payload of another type, a truncated one, one with trailing bytes, or one
// whose sizes disagree with its content throws DecodeError. The generated LCM
// code sizes arrays before it checks the buffer, so a bad length field can
// throw std::length_error or std::bad_alloc from inside decode: those become
// DecodeError too.
template <class Msg>
Msg DecodeMessage(const void* data, int size) {
  const std::string type = Msg::getTypeName();
  Msg msg;
  int used;
  try {
    used = msg.decode(data, 0, size);
  } catch (const std::exception& e) {
    throw DecodeError(type + ": malformed length field (" + e.what() + ")");
  }
  if (used < 0)
    throw DecodeError(type + ": does not decode (" + std::to_string(size) +
                      " bytes; another type, or truncated)");
  if (used != size)
    throw DecodeError(type + ": " + std::to_string(size - used) + " trailing bytes");
  Validate(msg);
  return msg;
}

// The encoding of msg; throws std::invalid_argument if it does not encode.
template <class Msg>
std::vector<uint8_t> EncodeMessage(const Msg& msg) {
  std::vector<uint8_t> bytes(size_t(msg.getEncodedSize()));
  if (msg.encode(bytes.data(), 0, int(bytes.size())) < 0)
    throw std::invalid_argument(Msg::getTypeName() + std::string(": does not encode"));
  return bytes;
}

}  // namespace ws
