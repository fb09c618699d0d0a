// The calibration file (calib/calib_file.h) read through OpenCV's YAML
// reader: anything it does not accept is a CalibrationFileError.
#include "calib/calib_file.h"
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    ws::calib::ReadCalibrationFile(ws::fuzz::WriteInputFile(data, size, ".yaml"));
  } catch (const ws::calib::CalibrationFileError&) {
  }
  return 0;
}
