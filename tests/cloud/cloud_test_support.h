// Helpers for the cloud tests: messages and scratch files.
#pragma once

#include <unistd.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lcm_io/point_cloud.h"

namespace ws::testing {

using Point = std::array<float, 3>;

// A consistent message holding `points`, with `intensity` (empty or one per
// point), utime 1000, frame_id 7, frame "left_rectified".
inline PointCloud MakeCloud(const std::vector<Point>& points,
                                           const std::vector<float>& intensity = {}) {
  PointCloud msg{};
  msg.utime = 1000;
  msg.frame_id = 7;
  msg.frame = "left_rectified";
  msg.npoints = int32_t(points.size());
  for (const Point& p : points) msg.xyz.push_back({p[0], p[1], p[2]});
  msg.nintensity = int32_t(intensity.size());
  msg.intensity = intensity;
  return msg;
}

// A noisy wall with outliers and invalid points (NoisyWallScene).
constexpr float kWallZ = 2.0f;         // metres
constexpr float kNoiseSigma = 0.005f;  // metres, along z
constexpr float kGridStep = 0.02f;     // metres; twice the default 1 cm leaf, so that no two
                                       // wall points share a voxel and none is averaged away
constexpr int kGridSide = 101;         // 2 m x 2 m
constexpr int kWallPoints = kGridSide * kGridSide;
constexpr int kStrayPoints = 500;  // uniform in the 2 x 2 x 3.5 m box in front of the wall
constexpr float kWallIntensity = 100, kOutlierIntensity = 7;

// The wall, outliers in range, and points every filter must drop: OpenCV's
// missing-disparity Z (10000), NaN, infinite, and behind the camera.
inline PointCloud NoisyWallScene() {
  std::mt19937 rng(42);
  std::normal_distribution<float> noise(0, kNoiseSigma);
  std::uniform_real_distribution<float> lateral(-1, 1), depth(0.5f, 4.0f);
  std::vector<Point> points;
  std::vector<float> intensity;
  auto add = [&](Point p, float i) {
    points.push_back(p);
    intensity.push_back(i);
  };
  // Offset by a quarter step so that no point sits on a voxel boundary.
  for (int row = 0; row < kGridSide; ++row)
    for (int col = 0; col < kGridSide; ++col)
      add({-1 + (col + 0.25f) * kGridStep, -1 + (row + 0.25f) * kGridStep, kWallZ + noise(rng)},
          kWallIntensity);
  for (int i = 0; i < kStrayPoints; ++i)
    add({lateral(rng), lateral(rng), depth(rng)}, kOutlierIntensity);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  for (int i = 0; i < 200; ++i) add({lateral(rng), lateral(rng), 10000}, 0);
  for (int i = 0; i < 100; ++i) add({nan, nan, nan}, 0);
  for (int i = 0; i < 50; ++i) add({lateral(rng), inf, 2}, 0);
  for (int i = 0; i < 50; ++i) add({lateral(rng), lateral(rng), -depth(rng)}, 0);
  return MakeCloud(points, intensity);
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
