// Time per stage of the stereo-cloud filter chain on clouds like those
// stereo-match publishes: one point per pixel of a rectified wide-angle
// camera looking at a wall and a floor, with depth noise that grows with
// depth squared, speckle outliers, and OpenCV's Z = 10000 where the
// disparity is missing. Prints the median wall time of several runs per
// stage, and the median CPU time of a whole run; then the outlier stage's
// statistic (cloud/outlier_removal.h) by its grid search and by its k-d tree
// against PCL's own single-threaded StatisticalOutlierRemoval on the same
// voxelized cloud, in alternating runs.
//
//   bench_cloud_filter [RUNS] [CLOUD.pcd ...]    (default 3 runs)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <random>
#include <string>
#include <vector>

#include <chrono>
#include <functional>
#include <utility>

#include <opencv2/core.hpp>
#include <pcl/filters/statistical_outlier_removal.h>

#include "bench_support.h"
#include "cloud/cloud_filter.h"
#include "cloud/cloud_stages.h"
#include "cloud/outlier_removal.h"
#include "cloud/pcd_io.h"
#include "cloud/pcl_cloud.h"

namespace {

using ws::bench::Median;

struct Camera {
  int width, height;
  double focal_px;  // square pixels, principal point at the centre
};

constexpr double kBaseline = 0.12;         // metres
constexpr double kDisparitySigma = 0.15;   // pixels, sub-pixel matcher
constexpr double kMissingFraction = 0.08;  // pixels without a disparity
constexpr double kSpeckleFraction = 0.02;  // wrong matches, anywhere along the ray
constexpr double kOpenCvMissingZ = 10000;  // reprojectImageTo3D(handleMissingValues)

// Depth along a ray (x, y, 1) to the nearer of a wall 2.5 m ahead (turned
// 15 degrees about the vertical) and a floor 1.2 m below the camera (y down).
double SceneDepth(double x, double y) {
  const double turn = 15 * M_PI / 180;
  const double wall = 2.5 / (std::cos(turn) + x * std::sin(turn));
  const double floor = y > 0 ? 1.2 / y : INFINITY;
  return std::min(wall > 0 ? wall : INFINITY, floor);
}

ws::PointCloud StereoWallCloud(const Camera& camera, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  std::normal_distribution<double> disparity_noise(0, kDisparitySigma);
  ws::PointCloud msg{};
  msg.frame = "left_rectified";
  msg.xyz.reserve(size_t(camera.width) * camera.height);
  for (int v = 0; v < camera.height; ++v)
    for (int u = 0; u < camera.width; ++u) {
      const double x = (u - camera.width / 2.0) / camera.focal_px;
      const double y = (v - camera.height / 2.0) / camera.focal_px;
      double z = SceneDepth(x, y);
      const double draw = unit(rng);
      if (draw < kMissingFraction) {
        z = kOpenCvMissingZ;
      } else if (draw < kMissingFraction + kSpeckleFraction) {
        z = 0.5 + 7.5 * unit(rng);
      } else {
        const double disparity = camera.focal_px * kBaseline / z + disparity_noise(rng);
        z = camera.focal_px * kBaseline / std::max(disparity, 0.5);
      }
      msg.xyz.push_back({float(x * z), float(y * z), float(z)});
      msg.intensity.push_back(float((u / 8 + v / 8) % 2 ? 200 : 50));
    }
  msg.npoints = msg.nintensity = int32_t(msg.xyz.size());
  return msg;
}

double MillisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// Wall and CPU (all threads) milliseconds of fn.
template <class Fn>
std::pair<double, double> Time(Fn&& fn) {
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();
  fn();
  return {MillisecondsSince(start), 1000.0 * double(std::clock() - cpu_start) / CLOCKS_PER_SEC};
}

// One way to compute the statistic and its CPU time per run.
struct Contender {
  const char* name;
  std::function<size_t()> kept;  // runs the statistic, returns the points kept
  std::vector<double> cpu_ms;
  size_t kept_points = 0;
};

// The outlier statistic on the same voxelised cloud three ways, in
// alternating runs: the grid search the chain uses on voxels, the k-d tree
// on every core (the chain's search before the grid, and still its search
// when the voxel stage is off), and PCL's own single-threaded filter.
void BenchOutliers(const ws::PointCloud& msg, int runs, const ws::CloudFilterConfig& config) {
  const ws::VoxelOutput voxels = ws::DownsampleVoxels(
      ws::KeepDepthRange(ws::ToPcl(msg), config.z_min, config.z_max), config.voxel_leaf);
  const ws::PclCloud::Ptr cloud = voxels.cloud;
  const int k = config.outliers_mean_k;
  const double mul = config.outliers_stddev_mul;
  std::vector<Contender> contenders = {
      {"grid", [&] { return ws::StatisticalInliers(cloud, k, mul, voxels.leaf).size(); }, {}, 0},
      {"k-d tree", [&] { return ws::StatisticalInliers(cloud, k, mul, 0).size(); }, {}, 0},
      {"PCL", [&] {
         pcl::StatisticalOutlierRemoval<pcl::PointXYZI> removal;
         removal.setInputCloud(cloud);
         removal.setMeanK(k);
         removal.setStddevMulThresh(mul);
         pcl::Indices kept;
         removal.filter(kept);
         return kept.size();
       }, {}, 0}};
  for (int run = 0; run < runs; ++run)
    for (Contender& c : contenders) c.cpu_ms.push_back(Time([&] { c.kept_points = c.kept(); }).second);
  const double pcl_cpu = Median(contenders.back().cpu_ms);
  std::printf("  outliers on %zu points (%d threads), median CPU ms, ratio to PCL's, points kept:\n",
              cloud->size(), cv::getNumThreads());
  for (const Contender& c : contenders)
    std::printf("    %-9s %8.1f  %5.3f  %zu\n", c.name, Median(c.cpu_ms), Median(c.cpu_ms) / pcl_cpu,
                c.kept_points);
}

// The chain with `config`, `runs` times: the median time per stage.
void BenchChain(const char* name, const ws::PointCloud& cloud, const ws::CloudFilterConfig& config,
                int runs) {
  const ws::CloudFilter filter{config};
  std::vector<widestereo::cloud_stats_t> stats;
  std::vector<double> cpu_ms;  // the chain is single-threaded: CPU time is its time alone
  for (int run = 0; run < runs; ++run) {
    const std::clock_t start = std::clock();
    stats.push_back(filter.Run(cloud).stats);
    cpu_ms.push_back(1000.0 * double(std::clock() - start) / CLOCKS_PER_SEC);
  }
  std::printf("  %s\n  %-12s %10s %12s\n", name, "stage", "points", "median ms");
  double total = 0;
  for (int stage = 0; stage < stats[0].nstages; ++stage) {
    std::vector<double> ms;
    for (const auto& s : stats) ms.push_back(s.stage_ms[stage]);
    total += Median(ms);
    std::printf("  %-12s %10d %12.1f\n", stats[0].stage_names[stage].c_str(),
                stats[0].stage_points[stage], Median(ms));
  }
  std::printf("  %-12s %10s %12.1f   (CPU %.1f ms: on a busy machine wall > CPU)\n", "sum", "",
              total, Median(cpu_ms));
  const auto& last = stats.back();
  std::printf("  plane: %s, normal (%.3f, %.3f, %.3f), offset %.3f m, inlier RMS %.1f mm\n",
              last.plane_found ? "found" : "not found", last.plane_normal[0], last.plane_normal[1],
              last.plane_normal[2], last.plane_offset, 1000 * last.inlier_rms);
}

// The default chain against the one before issue #16 (RANSAC on every
// point), then our outlier stage against PCL's.
void Bench(const char* name, const Camera& camera, int runs) {
  const ws::PointCloud cloud = StereoWallCloud(camera, 1);
  std::printf("\n%s: %dx%d = %d points, %d runs (leaf 1 cm)\n", name, camera.width, camera.height,
              cloud.npoints, runs);
  ws::CloudFilterConfig before;
  before.plane_ransac_points = 0;
  BenchChain("before #16: RANSAC on every point", cloud, before, runs);
  BenchChain("default: RANSAC on a subsample, refit on every inlier", cloud, ws::CloudFilterConfig{}, runs);
  BenchOutliers(cloud, runs, ws::CloudFilterConfig{});
}

// The live chain (config/stereo-cloud-live.yaml's voxels and neighbours) on
// `cloud`.
void BenchLive(const std::string& name, const ws::PointCloud& cloud, int runs) {
  ws::CloudFilterConfig live;
  live.voxel_leaf = 0.04;
  live.outliers_mean_k = 8;
  std::printf("\nlive: %s, %d points, %d runs (leaf 4 cm, 8 neighbours)\n", name.c_str(), cloud.npoints,
              runs);
  BenchChain("config/stereo-cloud-live.yaml", cloud, live, runs);
  BenchOutliers(cloud, runs, live);
}

constexpr char kUsage[] =
    "usage: bench_cloud_filter [RUNS >= 1] [CLOUD.pcd ...]\n"
    "  RUNS: runs per measurement (default 3). Each CLOUD.pcd (a cloud stereo-match published,\n"
    "  saved by stereo-cloud with every stage off, bench/cloud/README.md) goes through the live\n"
    "  chain too.\n";

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "--help") {
    std::printf("%s", kUsage);
    return 0;
  }
  const int runs = argc > 1 ? std::atoi(argv[1]) : 3;
  if (runs < 1) {
    std::fprintf(stderr, "%s", kUsage);
    return 2;
  }
  std::vector<ws::PointCloud> saved;
  for (int i = 2; i < argc; ++i) {
    try {
      saved.push_back(ws::ReadPcd(argv[i]));
    } catch (const std::exception& e) {
      std::fprintf(stderr, "bench_cloud_filter: %s: %s\n", argv[i], e.what());
      return 1;
    }
  }
  // Rectified 100-degree horizontal field: focal = (width / 2) / tan(50 deg).
  // stereo-match's live cloud: 1280x960 every 4th pixel and row.
  const Camera live{320, 240, 160 / std::tan(50 * M_PI / 180)};
  BenchLive("a made-up wall and floor, 320x240", StereoWallCloud(live, 1), runs);
  for (int i = 2; i < argc; ++i) BenchLive(argv[i], saved[size_t(i - 2)], runs);
  Bench("77 k", {320, 240, 160 / std::tan(50 * M_PI / 180)}, runs);
  Bench("0.3 M", {640, 480, 320 / std::tan(50 * M_PI / 180)}, runs);
  Bench("1 M", {1280, 800, 640 / std::tan(50 * M_PI / 180)}, runs);
  return 0;
}
