// The simulator's config (stereo-capture --source sim:CONFIG.yaml,
// sim/sim_config.h): anything it does not accept is a SimConfigError.
#include "fuzz_support.h"
#include "sim/sim_config.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    ws::ParseSimConfig(std::string(reinterpret_cast<const char*>(data), size), "fuzz.yaml",
                       WS_SOURCE_DIR "/config/sim");
  } catch (const ws::SimConfigError&) {
  }
  return 0;
}
