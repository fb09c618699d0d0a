// The camera settings of a rig file (config/rig/, capture/arv_camera_settings.h)
// read through OpenCV's YAML reader: anything it does not accept is a
// RigConfigError.
#include "capture/arv_camera_settings.h"
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    ws::LoadArvCameraSettings(ws::fuzz::WriteInputFile(data, size, ".yaml"));
  } catch (const ws::RigConfigError&) {
  }
  return 0;
}
