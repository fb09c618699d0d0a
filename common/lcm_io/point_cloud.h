// widestereo::point_cloud_t with its points in one array. The generated type
// holds each point in a std::vector of its own: a live STEREO_CLOUD of 73 k
// points was 73 k allocations to build or decode and as many frees, in
// stereo-match and again in stereo-cloud (bench/transport/README.md, "CPU
// per pair"). PointCloud has the same fields, each point a std::array, and
// LCM's message interface with the same fingerprint and encoding: it decodes
// every point_cloud_t and encodes to the bytes point_cloud_t would.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace ws {

struct PointCloud {
  int64_t utime = 0;
  int64_t frame_id = 0;
  std::string frame;                     // coordinate frame, e.g. "left_rectified"
  int32_t npoints = 0;                   // xyz.size()
  std::vector<std::array<float, 3>> xyz;  // metres
  int32_t nintensity = 0;                // 0 or npoints: intensity.size()
  std::vector<float> intensity;

  // LCM's message interface (Process::Publish and Subscribe, DecodeMessage).
  // encode returns -1 when the counts disagree with the arrays (the
  // generated code would read past them); decode returns -1 for what the
  // hardened generated decoder refuses (lcmtypes/harden_decoders.cmake).
  static const char* getTypeName();
  static int64_t getHash();
  int getEncodedSize() const;
  int encode(void* buf, int offset, int maxlen) const;
  int decode(const void* buf, int offset, int maxlen);
};

// What lcm_io/validate.h checks of a point_cloud_t, for DecodeMessage: throws
// DecodeError unless nintensity is 0 or npoints.
void Validate(const PointCloud& msg);

}  // namespace ws
