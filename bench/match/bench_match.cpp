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
// downscale, alternating. Last, the live SGBM against its other settings
// (block size, OpenCV's modes, one thread) on the live grid.
//
//   bench_match [RUNS]    (default 5)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iterator>
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

// The live matcher's SGBM against the settings it could use instead, bare
// OpenCV on the same pair rectified to the live grid: each one's median time,
// its density and the share of the pixels both match whose disparities agree
// within one pixel; and the live settings on one thread.
void CompareSgbmSettings(const ws::MatcherConfig& live, const ws::Rig& rig, const widestereo::stereo_frame_t& frame,
                         int runs) {
  ws::RectifyOptions options;
  options.downscale = live.downscale;
  const ws::Rectification grid = ws::BuildRectification(rig, options);
  cv::Mat left, right;
  ws::RectifyPair(grid, ws::ImageToMat(frame.left), ws::ImageToMat(frame.right), &left, &right);
  const ws::MatcherConfig at_grid = ws::AtMatchScale(live);
  struct Variant {
    const char* name;
    int block_size;
    int mode;
    int threads;  // 0: OpenCV's default
  };
  const Variant variants[] = {{"3-way, block 7 (live)", 7, cv::StereoSGBM::MODE_SGBM_3WAY, 0},
                              {"3-way, block 5", 5, cv::StereoSGBM::MODE_SGBM_3WAY, 0},
                              {"3-way, block 3", 3, cv::StereoSGBM::MODE_SGBM_3WAY, 0},
                              {"HH4", 7, cv::StereoSGBM::MODE_HH4, 0},
                              {"8 paths (sgbm)", 7, cv::StereoSGBM::MODE_SGBM, 0},
                              {"3-way, block 7, one thread", 7, cv::StereoSGBM::MODE_SGBM_3WAY, 1}};
  std::printf("SGBM on the live %dx%d grid, %d disparities (bare OpenCV, no margin):\n", left.cols, left.rows,
              at_grid.num_disparities);
  const int threads = cv::getNumThreads();
  const size_t n = std::size(variants);
  std::vector<cv::Ptr<cv::StereoSGBM>> matchers;
  for (const Variant& v : variants) {
    ws::MatcherConfig config = at_grid;
    config.block_size = v.block_size;
    matchers.push_back(ws::MakeMatcher(config).dynamicCast<cv::StereoSGBM>());
    matchers.back()->setMode(v.mode);
  }
  // Alternating runs: a machine whose speed drifts slows each alike.
  std::vector<cv::Mat> disparities(n);
  std::vector<std::vector<double>> ms(n);
  for (int run = 0; run < runs; ++run)
    for (size_t i = 0; i < n; ++i) {
      if (variants[i].threads > 0) cv::setNumThreads(variants[i].threads);
      ms[i].push_back(Milliseconds([&] { matchers[i]->compute(left, right, disparities[i]); }));
      cv::setNumThreads(threads);
    }
  const cv::Mat& reference = disparities[0];
  for (size_t i = 0; i < n; ++i) {
    const cv::Mat valid = disparities[i] >= 0, both = valid & (reference >= 0);
    cv::Mat difference;
    cv::absdiff(disparities[i], reference, difference);
    const double agree = cv::countNonZero(both & (difference <= cv::StereoMatcher::DISP_SCALE));
    std::printf("  %-28s %7.1f ms  density %.3f  agreeing with the live within 1 px %.4f\n", variants[i].name,
                Median(ms[i]), cv::countNonZero(valid) / double(valid.total()), agree / cv::countNonZero(both));
  }
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
  CompareSgbmSettings(live, rig, frame, runs);
  return 0;
}
