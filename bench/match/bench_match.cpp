// stereo-match's per-frame work on a 1280 x 960 pair against bare OpenCV on
// the same images: cv::remap with the same fixed-point maps and the same
// matcher object's compute(). The pair is the simulator's random-dot wall
// through the ~125 deg Theia-like rig. Runs alternate between the two, and
// the medians are compared; for SGBM (stereo-match's default settings) and
// for BM with the paper's 33 x 33 window. Then stereo-match's rectify and
// match with the live settings (config/stereo-match-live.yaml) on the common
// field's region (match/match_region.h) against the whole image, alternating;
// and rectifying straight to the matcher's grid (RectifyOptions::downscale,
// what stereo-match does) against the full-size remap and the matcher's own
// downscale, alternating.
//
//   bench_match [RUNS]    (default 5)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "lcm_io/image_codec.h"
#include "match/match_node.h"
#include "match/match_region.h"
#include "sim/simulator.h"
#include "bench_support.h"
#include "sim/truth_calibration.h"

using ws::bench::Median;
using ws::bench::Milliseconds;

namespace {

void Compare(const char* name, const ws::MatchConfig& config, const ws::Rectification& rect,
             const widestereo::stereo_frame_t& frame, int runs) {
  const cv::Mat left = ws::ImageToMat(frame.left), right = ws::ImageToMat(frame.right);
  const cv::Ptr<cv::StereoMatcher> matcher = ws::MakeMatcher(config.matcher);
  ws::DisparityMatcher ours(config.matcher);
  std::vector<double> pipeline, rectify_match, bare;
  size_t points = 0;
  for (int run = 0; run < runs; ++run) {
    pipeline.push_back(Milliseconds([&] { points = ws::MatchFrame(rect, ours, config.cloud, frame).cloud.xyz.size(); }));
    rectify_match.push_back(Milliseconds([&] {
      cv::Mat lr, rr;
      ws::RectifyPair(rect, left, right, &lr, &rr);
      ours.Compute(lr, rr);
    }));
    bare.push_back(Milliseconds([&] {
      cv::Mat lr, rr, disparity;
      cv::remap(left, lr, rect.maps_left[0][0], rect.maps_left[0][1], cv::INTER_LINEAR);
      cv::remap(right, rr, rect.maps_right[0][0], rect.maps_right[0][1], cv::INTER_LINEAR);
      matcher->compute(lr, rr, disparity);
    }));
  }
  std::printf("%-34s bare OpenCV %8.1f ms | rectify + match %8.1f ms (%.3f) | whole frame, "
              "disparity + %zu-point cloud %8.1f ms (%.3f)\n",
              name, Median(bare), Median(rectify_match), Median(rectify_match) / Median(bare), points,
              Median(pipeline), Median(pipeline) / Median(bare));
}

void CompareRegion(const char* name, ws::MatcherConfig config, const ws::Rectification& rect,
                   const widestereo::stereo_frame_t& frame, int runs) {
  const auto shared = std::make_shared<const ws::Rectification>(rect);
  config.common_field_only = true;
  const cv::Rect region = ws::MatchRegion(rect, config);
  ws::DisparityMatcher common(config);
  config.common_field_only = false;
  ws::DisparityMatcher whole(config);
  std::vector<double> common_ms, whole_ms;
  for (int run = 0; run < runs; ++run) {
    common_ms.push_back(Milliseconds([&] { ws::RectifyAndMatch(shared, common, frame); }));
    whole_ms.push_back(Milliseconds([&] { ws::RectifyAndMatch(shared, whole, frame); }));
  }
  std::printf("%-34s common field %dx%d at (%d, %d), matched region %dx%d: rectify + match %8.1f ms, "
              "whole %dx%d image %8.1f ms (%.3f)\n",
              name, rect.common.width, rect.common.height, rect.common.x, rect.common.y, region.width,
              region.height, Median(common_ms), rect.size.width, rect.size.height, Median(whole_ms),
              Median(common_ms) / Median(whole_ms));
}

void CompareGrid(const char* name, const ws::MatcherConfig& config, const ws::Rig& rig,
                 const widestereo::stereo_frame_t& frame, int runs) {
  ws::RectifyOptions options;
  const auto full = std::make_shared<const ws::Rectification>(ws::BuildRectification(rig, options));
  options.downscale = config.downscale;
  const auto grid = std::make_shared<const ws::Rectification>(ws::BuildRectification(rig, options));
  ws::DisparityMatcher full_matcher(config), grid_matcher(ws::AtMatchScale(config));
  const cv::Mat left = ws::ImageToMat(frame.left), right = ws::ImageToMat(frame.right);
  std::vector<double> full_ms, grid_ms, full_rectify_ms, grid_rectify_ms;
  for (int run = 0; run < runs; ++run) {
    cv::Mat lr, rr;
    full_rectify_ms.push_back(Milliseconds([&] { ws::RectifyPair(*full, left, right, &lr, &rr); }));
    grid_rectify_ms.push_back(Milliseconds([&] { ws::RectifyPair(*grid, left, right, &lr, &rr); }));
    full_ms.push_back(Milliseconds([&] { ws::RectifyAndMatch(full, full_matcher, frame); }));
    grid_ms.push_back(Milliseconds([&] { ws::RectifyAndMatch(grid, grid_matcher, frame); }));
  }
  std::printf("%-34s rectify: at the matcher's %dx%d grid %6.1f ms, full size %6.1f ms (%.3f); rectify + match: "
              "%6.1f ms, full size + downscale %6.1f ms (%.3f)\n",
              name, grid->size.width, grid->size.height, Median(grid_rectify_ms), Median(full_rectify_ms),
              Median(grid_rectify_ms) / Median(full_rectify_ms), Median(grid_ms), Median(full_ms),
              Median(grid_ms) / Median(full_ms));
}

}  // namespace

int main(int argc, char** argv) {
  const int runs = argc > 1 ? std::atoi(argv[1]) : 5;
  if (runs < 1) {
    std::fprintf(stderr, "usage: bench_match [RUNS >= 1]\n");
    return 2;
  }
  ws::SimConfig sim = ws::DefaultSimConfig();
  sim.board.reset();  // the wall only
  const ws::Simulator simulator(sim);
  const auto [left, right] = simulator.Render(0);
  widestereo::stereo_frame_t frame{};
  frame.left = ws::MatToImage(left, 0);
  frame.right = ws::MatToImage(right, 0);
  const ws::Rig rig = ws::TrueStereoRig(sim);
  const ws::Rectification rect = ws::BuildRectification(rig);
  std::printf("%dx%d pair, median of %d alternating runs; ratios against bare OpenCV\n", left.cols, left.rows,
              runs);

  ws::MatchConfig sgbm;  // stereo-match's defaults: SGBM, 128 disparities, 7 x 7
  Compare("sgbm 128 disparities, block 7", sgbm, rect, frame, runs);
  ws::MatchConfig bm;
  bm.matcher.kind = "bm";
  bm.matcher.block_size = 33;  // the paper's window
  Compare("bm 128 disparities, block 33", bm, rect, frame, runs);

  ws::MatcherConfig live;  // config/stereo-match-live.yaml
  live.kind = "sgbm3way";
  live.downscale = 2;
  CompareRegion("live settings, focal scale 1", live, rect, frame, runs);
  CompareRegion("live settings, focal scale 0.7", live,
                ws::BuildRectification(rig, {0.7, {}, ws::RectificationMode::kPinhole}), frame, runs);
  CompareGrid("live settings, matcher's grid", live, rig, frame, runs);
  return 0;
}
