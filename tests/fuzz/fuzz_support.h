// What the libFuzzer targets in tests/fuzz share. Each target is one
// LLVMFuzzerTestOneInput; built with WS_FUZZ it is a libFuzzer binary, in the
// normal build it is linked with replay_main.cpp and ctest replays its corpus.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "auth/rig_key.h"
#include "lcm_io/decode.h"

namespace ws::fuzz {

// A property every accepted input must have is broken: report and abort, so
// that libFuzzer keeps the input as a crash and replay fails.
[[noreturn]] inline void Violated(const std::string& what) {
  std::fprintf(stderr, "fuzz property violated: %s\n", what.c_str());
  std::abort();
}

template <class Msg>
std::vector<uint8_t> Encode(const Msg& msg) {
  std::vector<uint8_t> bytes(size_t(msg.getEncodedSize()));
  const int used = msg.encode(bytes.data(), 0, int(bytes.size()));
  if (used != int(bytes.size()))
    Violated(std::string(Msg::getTypeName()) + ": encode wrote " + std::to_string(used) +
             " bytes, getEncodedSize() said " + std::to_string(bytes.size()));
  return bytes;
}

// Decodes the input as a process does (DecodeMessage: LCM decode, then
// Validate). A message it accepts must survive being published again: its
// encoding is accepted too and encodes to the same bytes.
template <class Msg>
std::optional<Msg> DecodeAccepted(const uint8_t* data, size_t size) {
  std::optional<Msg> msg;
  try {
    msg = DecodeMessage<Msg>(data, int(size));
  } catch (const DecodeError&) {
    return std::nullopt;
  }
  const std::vector<uint8_t> bytes = Encode(*msg);
  try {
    if (Encode(DecodeMessage<Msg>(bytes.data(), int(bytes.size()))) != bytes)
      Violated(std::string(Msg::getTypeName()) + ": re-encoding an accepted message changes it");
  } catch (const DecodeError& e) {
    Violated(std::string(Msg::getTypeName()) + ": an accepted message, re-encoded, is rejected: " +
             e.what());
  }
  return msg;
}

// The rig key of the seeds and the corpus (public, never a rig's): the
// commands and calibrations signed with it pass the MAC check.
inline const auth::RigKey& FuzzKey() {
  static const auth::RigKey key = auth::RigKey::FromSecret("widestereo fuzz corpus key: public, never a rig's");
  return key;
}

// The input as a file, for readers that take a path. One file per process,
// overwritten by every input.
std::string WriteInputFile(const uint8_t* data, size_t size, const std::string& extension);

}  // namespace ws::fuzz
