// PCD files (cloud/pcd_io.h) in any of PCL's encodings: anything ReadPcd does
// not accept is a PcdError, and what it accepts is a consistent cloud.
#include "cloud/pcd_io.h"
#include "cloud/point_cloud_check.h"
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  ws::PointCloud cloud;
  try {
    cloud = ws::ReadPcd(ws::fuzz::WriteInputFile(data, size, ".pcd"));
  } catch (const ws::PcdError&) {
    return 0;
  }
  try {
    ws::ValidatePointCloud(cloud);
  } catch (const ws::DecodeError& e) {
    ws::fuzz::Violated(std::string("ReadPcd gave an inconsistent cloud: ") + e.what());
  }
  return 0;
}
