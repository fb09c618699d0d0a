// stereo-health's cost per checked frame and what it measures, on the
// simulator's ~125 deg Theia-like rig (1280 x 960) with its true images:
//
//  1. cost: one checked frame (rectify both images, corners, descriptors,
//     matching, Lucas-Kanade, RANSAC, dy and rays), median over RUNS, on a
//     wall frame and a board frame, with OpenCV on every core it has
//     (run under `taskset -c 0,1` for 2 cores);
//  2. the calibration's right camera pitched (about x) and rolled (about z)
//     by several angles: median and 95th percentile |dy| measured through
//     it, the refinement from those matches, |dy| measured again through
//     the refined calibration, and how far the refined R is from the true
//     one; on 3 wall frames (one depth), then on those and 12 board poses.
//
//   bench_health [RUNS]    (default 10)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "health/dy_figures.h"
#include "health/extrinsic_refine.h"
#include "health/frame_checker.h"
#include "sim/simulator.h"
#include "bench_support.h"
#include "sim/truth_calibration.h"

using ws::bench::Median;

namespace {

constexpr double kDeg = M_PI / 180;

ws::Rig Turned(const ws::Rig& rig, const Eigen::Vector3d& axis, double deg) {
  const Eigen::Matrix3d Q = Eigen::AngleAxisd(deg * kDeg, axis).toRotationMatrix();
  ws::Rig turned = rig;
  turned.R = Q * rig.R;
  turned.T = Q * rig.T;
  return turned;
}

using Pairs = std::vector<std::pair<cv::Mat, cv::Mat>>;

// Every match of the frames through `rig`'s rectification.
ws::FrameCheck CheckAll(const ws::Rig& rig, const Pairs& pairs) {
  const ws::FrameChecker checker(rig, {}, {});
  ws::FrameCheck all;
  for (const auto& [left, right] : pairs) {
    ws::FrameCheck c = checker.Check(left, right, "the calibration");
    all.dy.insert(all.dy.end(), c.dy.begin(), c.dy.end());
    all.rays.insert(all.rays.end(), c.rays.begin(), c.rays.end());
  }
  return all;
}

void Cost(const char* name, const ws::Rig& rig, const std::pair<cv::Mat, cv::Mat>& pair, int runs) {
  const ws::FrameChecker checker(rig, {}, {});
  std::vector<double> ms;
  size_t matches = 0;
  for (int run = 0; run < runs; ++run) {
    const auto start = std::chrono::steady_clock::now();
    matches = checker.Check(pair.first, pair.second, "the calibration").dy.size();
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  std::printf("%-6s frame: %4zu matches, %6.1f ms per checked frame (median of %d; min %.1f, max %.1f)\n", name,
              matches, Median(ms), runs, *std::min_element(ms.begin(), ms.end()),
              *std::max_element(ms.begin(), ms.end()));
}

void Sweep(const char* scene, const ws::Rig& truth, const Pairs& pairs) {
  std::printf("\n%s\n%-6s %7s | %-27s | %-27s | %s\n", scene, "error", "deg", "before: median / p95 |dy| px",
              "after refine: median / p95", "refined R from the truth, deg");
  const ws::Rectification true_rect = ws::BuildRectification(truth);
  const ws::DyFigures exact = ws::ComputeDyFigures(CheckAll(truth, pairs).dy, true_rect.size, {});
  std::printf("%-6s %7s | %12.3f / %-12.3f |\n", "none", "", exact.median_abs, exact.p95_abs);
  for (const auto& [name, axis] : {std::pair{"pitch", Eigen::Vector3d::UnitX()}, std::pair{"roll", Eigen::Vector3d::UnitZ()}})
    for (double deg : {0.02, 0.05, 0.1, 0.2, 0.3, 0.5, 1.0}) {
      const ws::Rig wrong = Turned(truth, axis, deg);
      const ws::FrameCheck before = CheckAll(wrong, pairs);
      const ws::DyFigures fb = ws::ComputeDyFigures(before.dy, true_rect.size, {});
      const ws::Rectification rect = ws::BuildRectification(wrong);
      const ws::RefineResult r = ws::RefineExtrinsics(wrong, rect.f, before.rays, rect.size, {}, {});
      if (!r.applied) {
        std::printf("%-6s %7.2f | %12.3f / %-12.3f | refused: %s\n", name, deg, fb.median_abs, fb.p95_abs,
                    r.refused.c_str());
        continue;
      }
      const ws::DyFigures fa = ws::ComputeDyFigures(CheckAll(r.rig, pairs).dy, true_rect.size, {});
      const double error = Eigen::AngleAxisd(r.rig.R * truth.R.transpose()).angle() / kDeg;
      std::printf("%-6s %7.2f | %12.3f / %-12.3f | %12.3f / %-12.3f | %.4f  (%d of %d matches)\n", name, deg,
                  fb.median_abs, fb.p95_abs, fa.median_abs, fa.p95_abs, error, r.matches_used, r.matches);
    }
}

}  // namespace

int main(int argc, char** argv) {
  const int runs = argc > 1 ? std::atoi(argv[1]) : 10;
  if (runs < 1) {
    std::fprintf(stderr, "usage: bench_health [RUNS >= 1]\n");
    return 2;
  }
  const ws::SimConfig sim = ws::DefaultSimConfig();
  const ws::Simulator simulator(sim);
  const ws::Rig truth = ws::TrueStereoRig(sim);
  const int first_wall = int(sim.board->poses);
  Pairs wall;
  for (int f = first_wall; f < first_wall + 3; ++f) wall.push_back(simulator.Render(f));
  std::printf("OpenCV threads: %d\n", cv::getNumThreads());
  Cost("wall", truth, wall.front(), runs);
  Cost("board", truth, simulator.Render(7), runs);

  Pairs mixed = wall;
  for (int f = 0; f < 12; ++f) mixed.push_back(simulator.Render(f));
  for (const auto& [scene, pairs] : {std::pair{"3 wall frames", &wall}, std::pair{"3 wall frames + 12 board poses", &mixed}})
    Sweep(scene, truth, *pairs);
  return 0;
}
