// Lat-lon against pinhole rectification (rectify/rectification.h) at the
// same output size and focal length, in one run: building the maps (once
// per calibration) and stereo-match's per-frame work (rectify + match +
// triangulate the cloud, MatchFrame). The pairs: the simulator's ~125 deg
// Theia-like rig at its wall, and its 200-degree rig inside the box room
// (config/sim/fisheye.yaml's room scene). The output size is the lat-lon image of the common
// field at the cameras' central resolution; the pinhole is given that size.
// Runs alternate between the modes; medians and their ratios are printed,
// per frame also for its two stages (RectifyAndMatch, ToMessages).
//
//   bench_rectification_modes [RUNS]    (default 5)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "lcm_io/image_codec.h"
#include "match/match_node.h"
#include "sim/simulator.h"
#include "bench_support.h"
#include "sim/truth_calibration.h"

using ws::bench::Median;
using ws::bench::Milliseconds;

namespace {

void Compare(const char* name, const ws::SimConfig& sim, int runs) {
  const ws::Simulator simulator(sim);
  const auto [left, right] = simulator.Render(simulator.frame_count() - 1);
  widestereo::stereo_frame_t frame{};
  frame.left = ws::MatToImage(left, 0);
  frame.right = ws::MatToImage(right, 0);
  const ws::Rig rig = ws::TrueStereoRig(sim);
  ws::RectifyOptions options[2];
  options[0].mode = ws::RectificationMode::kLatLon;
  options[1].mode = ws::RectificationMode::kPinhole;
  ws::Rectification rect[2];
  std::vector<double> build[2], per_frame[2];
  for (int run = 0; run < runs; ++run)
    for (int m = 0; m < 2; ++m) {
      build[m].push_back(Milliseconds([&] { rect[m] = ws::BuildRectification(rig, options[m]); }));
      options[1].size = rect[0].size;  // the pinhole at the lat-lon image's size
    }
  ws::MatchConfig config;  // stereo-match's defaults
  config.matcher.kind = "sgbm3way";
  config.cloud.step = 2;
  ws::DisparityMatcher matcher(config.matcher);
  size_t points[2] = {0, 0};
  std::vector<double> rectify_match[2], cloud[2];
  for (int run = 0; run < runs; ++run)
    for (int m = 0; m < 2; ++m) {
      // MatchFrame's two stages, timed apart.
      const std::shared_ptr<const ws::Rectification> view(&rect[m], [](const ws::Rectification*) {});
      ws::MatchedFrame matched;
      rectify_match[m].push_back(Milliseconds([&] { matched = ws::RectifyAndMatch(view, matcher, frame); }));
      cloud[m].push_back(Milliseconds(
          [&] { points[m] = ws::ToMessages(matched, config.matcher, config.cloud).cloud.xyz.size(); }));
      per_frame[m].push_back(rectify_match[m].back() + cloud[m].back());
    }
  std::printf("%s: %dx%d input, %dx%d rectified at f %.1f px\n", name, left.cols, left.rows, rect[0].size.width,
              rect[0].size.height, rect[0].f);
  std::printf("  maps, once per calibration:        latlon %8.1f ms | pinhole %8.1f ms | ratio %.3f\n",
              Median(build[0]), Median(build[1]), Median(build[0]) / Median(build[1]));
  std::printf("  rectify + match + cloud, a frame:  latlon %8.1f ms | pinhole %8.1f ms | ratio %.3f "
              "(%zu / %zu points)\n",
              Median(per_frame[0]), Median(per_frame[1]), Median(per_frame[0]) / Median(per_frame[1]), points[0],
              points[1]);
  std::printf("    of which rectify + match:       latlon %8.1f ms | pinhole %8.1f ms | ratio %.3f\n",
              Median(rectify_match[0]), Median(rectify_match[1]), Median(rectify_match[0]) / Median(rectify_match[1]));
  std::printf("    and the disparity + cloud:      latlon %8.1f ms | pinhole %8.1f ms | ratio %.3f\n",
              Median(cloud[0]), Median(cloud[1]), Median(cloud[0]) / Median(cloud[1]));
}

}  // namespace

int main(int argc, char** argv) {
  const int runs = argc > 1 ? std::atoi(argv[1]) : 5;
  if (runs < 1) {
    std::fprintf(stderr, "usage: bench_rectification_modes [RUNS >= 1]\n");
    return 2;
  }
  std::printf("median of %d alternating runs, sgbm3way, 128 disparities, cloud step 2\n", runs);
  ws::SimConfig theia = ws::DefaultSimConfig();
  theia.board.reset();  // the wall only
  Compare("Theia-like ~125 deg rig, wall at 2 m", theia, runs);
  ws::SimConfig fisheye = ws::LoadSimConfig("config/sim/fisheye.yaml");
  fisheye.board.reset();  // the room only
  fisheye.wall.reset();
  Compare("200-degree rig in a box room", fisheye, runs);
  return 0;
}
