// Point clouds as PCD files (PCL's format).
#pragma once

#include <stdexcept>
#include <string>

#include "lcm_io/point_cloud.h"

namespace ws {

struct PcdError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Writes a binary PCD with fields x y z, plus intensity when the message has
// it. Throws DecodeError for an inconsistent message (ValidatePointCloud) and
// PcdError naming the path when the file cannot be written.
void WritePcd(const std::string& path, const PointCloud& msg);

// Reads a PCD file (any of PCL's encodings) with fields x y z and optionally
// intensity. PCD has no time or frame: utime and frame_id are 0, frame empty.
// Throws PcdError naming the path.
PointCloud ReadPcd(const std::string& path);

}  // namespace ws
