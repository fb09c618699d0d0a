// stereo-match's per-frame work on a 1280 x 960 pair against bare OpenCV on
// the same images: cv::remap with the same fixed-point maps and the same
// matcher object's compute(). The pair is the simulator's random-dot wall
// through the ~125 deg Theia-like rig. Runs alternate between the two, and
// the medians are compared; for SGBM (stereo-match's default settings) and
// for BM with the paper's 33 x 33 window.
//
//   bench_match [RUNS]    (default 5)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "lcm_io/image_codec.h"
#include "match/match_node.h"
#include "sim/simulator.h"
#include "bench_support.h"

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
      cv::remap(left, lr, rect.map_left[0], rect.map_left[1], cv::INTER_LINEAR);
      cv::remap(right, rr, rect.map_right[0], rect.map_right[1], cv::INTER_LINEAR);
      matcher->compute(lr, rr, disparity);
    }));
  }
  std::printf("%-34s bare OpenCV %8.1f ms | rectify + match %8.1f ms (%.3f) | whole frame, "
              "disparity + %zu-point cloud %8.1f ms (%.3f)\n",
              name, Median(bare), Median(rectify_match), Median(rectify_match) / Median(bare), points,
              Median(pipeline), Median(pipeline) / Median(bare));
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
  const ws::Rectification rect = ws::BuildRectification(ws::bench::TrueRig(sim));
  std::printf("%dx%d pair, median of %d alternating runs; ratios against bare OpenCV\n", left.cols, left.rows,
              runs);

  ws::MatchConfig sgbm;  // stereo-match's defaults: SGBM, 128 disparities, 7 x 7
  Compare("sgbm 128 disparities, block 7", sgbm, rect, frame, runs);
  ws::MatchConfig bm;
  bm.matcher.kind = "bm";
  bm.matcher.block_size = 33;  // the paper's window
  Compare("bm 128 disparities, block 33", bm, rect, frame, runs);
  return 0;
}
