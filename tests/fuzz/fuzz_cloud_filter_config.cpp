// The stereo-cloud filter settings (cloud/cloud_filter_config.h) read through
// OpenCV's YAML reader: anything it does not accept is a ConfigError.
#include "cloud/cloud_filter_config.h"
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    ws::LoadCloudFilterConfig(ws::fuzz::WriteInputFile(data, size, ".yaml"));
  } catch (const ws::ConfigError&) {
  }
  return 0;
}
