// Other tools' calibration files as LoadAnyRig reads them (interop/any_rig.h):
// ROS camera_info, Kalibr camchain and OpenCV YAML, told apart by their
// keys. Anything it does not accept is a CalibrationFileError.
#include "fuzz_support.h"
#include "interop/any_rig.h"
#include "rig/rig_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    ws::LoadAnyRig(ws::fuzz::WriteInputFile(data, size, ".yaml"));
  } catch (const ws::CalibrationFileError&) {
  }
  return 0;
}
