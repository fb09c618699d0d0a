// Helpers for the cloud tests: messages and scratch files.
#pragma once

#include <unistd.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "widestereo/point_cloud_t.hpp"

namespace ws::testing {

using Point = std::array<float, 3>;

// A consistent message holding `points`, with `intensity` (empty or one per
// point), utime 1000, frame_id 7, frame "left_rectified".
inline widestereo::point_cloud_t MakeCloud(const std::vector<Point>& points,
                                           const std::vector<float>& intensity = {}) {
  widestereo::point_cloud_t msg{};
  msg.utime = 1000;
  msg.frame_id = 7;
  msg.frame = "left_rectified";
  msg.npoints = int32_t(points.size());
  for (const Point& p : points) msg.xyz.push_back({p[0], p[1], p[2]});
  msg.nintensity = int32_t(intensity.size());
  msg.intensity = intensity;
  return msg;
}

// A file path unique to this process (tests may run in parallel: ctest -j,
// or two build trees at once), optionally written with `contents`; the file
// is removed when the ScratchFile goes out of scope.
class ScratchFile {
 public:
  explicit ScratchFile(const std::string& name)
      : path_(::testing::TempDir() + "ws_cloud_" + std::to_string(::getpid()) + "_" + name) {}
  ScratchFile(const std::string& name, const std::string& contents) : ScratchFile(name) {
    std::ofstream(path_) << contents;
  }
  ScratchFile(const ScratchFile&) = delete;
  ScratchFile& operator=(const ScratchFile&) = delete;
  ~ScratchFile() { std::remove(path_.c_str()); }

  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace ws::testing
