#include "cloud/point_cloud_check.h"

#include <string>

namespace ws {
namespace {

[[noreturn]] void Reject(const std::string& what) { throw DecodeError("point_cloud_t: " + what); }

std::string Count(int64_t n) { return std::to_string(n); }

}  // namespace

void ValidatePointCloud(const PointCloud& msg) {
  if (msg.npoints < 0) Reject("negative npoints " + Count(msg.npoints));
  if (msg.nintensity < 0) Reject("negative nintensity " + Count(msg.nintensity));
  if (msg.xyz.size() != size_t(msg.npoints))
    Reject("npoints is " + Count(msg.npoints) + " but xyz holds " + Count(msg.xyz.size()) +
           " points");
  if (msg.nintensity != 0 && msg.nintensity != msg.npoints)
    Reject("nintensity is " + Count(msg.nintensity) + ", must be 0 or npoints (" +
           Count(msg.npoints) + ")");
  if (msg.intensity.size() != size_t(msg.nintensity))
    Reject("nintensity is " + Count(msg.nintensity) + " but intensity holds " +
           Count(msg.intensity.size()) + " values");
}

}  // namespace ws
