// Building stereo-match's rectification maps (through the full lens model,
// rectify/rectification.h) for one calibration of each model, against
// OpenCV's cv::stereoRectify + cv::initUndistortRectifyMap for a pinhole rig
// with the 5-coefficient Brown model at the same size, in the same process.
// The lenses: the simulator's Theia-like ~125 deg lens as a B-spline and
// fitted as poly6 and poly12 (sim_config.h, `fit:`), 1280 x 960.
//
//   bench_rectify_maps [RUNS]    (default 5)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include <opencv2/calib3d.hpp>

#include "rectify/rectification.h"
#include "sim/sim_config.h"
#include "bench_support.h"

using ws::bench::Median;
using ws::bench::Milliseconds;

namespace {

ws::Rig TheiaRig(const std::string& kind) {
  const ws::SimConfig sim = ws::ParseSimConfig(
      "rig: {baseline: 0.3, left: {lens: theia, fit: " + kind + "}}\nscene: {wall: {frames: 1}}\n",
      "bench_rectify_maps", ".");
  ws::Rig rig;
  rig.left = rig.right = sim.left;
  rig.T = Eigen::Vector3d(sim.T[0], sim.T[1], sim.T[2]);
  return rig;
}

// OpenCV's maps for a pinhole rig of the same size, focal length and baseline.
void OpenCvMaps(const ws::CameraModel& camera, cv::Mat maps[4]) {
  const cv::Matx33d K(camera.fx, 0, camera.cx, 0, camera.fy, camera.cy, 0, 0, 1);
  const cv::Matx<double, 1, 5> dist(-0.05, 0.004, 0, 0, -0.0001);
  const cv::Size size(camera.image_width, camera.image_height);
  cv::Mat R1, R2, P1, P2, Q;
  cv::stereoRectify(K, dist, K, dist, size, cv::Matx33d::eye(), cv::Vec3d(-0.3, 0, 0), R1, R2, P1, P2, Q, 0);
  cv::initUndistortRectifyMap(K, dist, R1, P1, size, CV_16SC2, maps[0], maps[1]);
  cv::initUndistortRectifyMap(K, dist, R2, P2, size, CV_16SC2, maps[2], maps[3]);
}

}  // namespace

int main(int argc, char** argv) {
  const int runs = argc > 1 ? std::atoi(argv[1]) : 5;
  if (runs < 1) {
    std::fprintf(stderr, "usage: bench_rectify_maps [RUNS >= 1]\n");
    return 2;
  }
  std::printf("maps for both cameras, 1280x960, median of %d alternating runs\n", runs);
  for (const std::string kind : {"bspline", "poly6", "poly12"}) {
    const ws::Rig rig = TheiaRig(kind);
    std::vector<double> ours, opencv;
    for (int run = 0; run < runs; ++run) {
      ours.push_back(Milliseconds([&] { ws::BuildRectification(rig); }));
      opencv.push_back(Milliseconds([&] {
        cv::Mat maps[4];
        OpenCvMaps(rig.left, maps);
      }));
    }
    std::printf("  %-8s %8.1f ms | OpenCV pinhole + 5 coefficients %6.1f ms | ratio %.1f\n", kind.c_str(),
                Median(ours), Median(opencv), Median(ours) / Median(opencv));
  }
  return 0;
}
