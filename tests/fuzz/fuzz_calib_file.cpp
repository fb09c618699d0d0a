// The calibration file (rig/rig_file.h) read through OpenCV's YAML
// reader: anything it does not accept is a CalibrationFileError.
#include "fuzz_support.h"
#include "rig/rig_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    ws::ReadCalibrationFile(ws::fuzz::WriteInputFile(data, size, ".yaml"));
  } catch (const ws::CalibrationFileError&) {
  }
  return 0;
}
