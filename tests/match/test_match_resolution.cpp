// Rectifying straight to the matcher's resolution (RectifyOptions::downscale,
// what stereo-match does) against the full-size remap followed by the
// matcher's own area downscale (what it did before), on the simulator's wall
// with the live settings (config/stereo-match-live.yaml): the same
// disparities, within 0.1 px (measured: the same values), and a cloud as
// close to the true wall. The wall's accuracy through the processes is
// FlatWall.FastMatcherModesKeepTheWallAtTwoMetres.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "lcm_io/image_codec.h"
#include "match/match_node.h"
#include "source/sim_source.h"

namespace {

bool Valid(float d) { return std::isfinite(d) && d > 0; }

TEST(MatchResolution, RemapAtTheMatchersResolutionGivesTheDisparityOfAFullSizeRemapAndDownscale) {
  auto source = ws::MakeSimSource("config/sim/wall.yaml", false);
  const auto pair = source->Next();
  ASSERT_TRUE(pair);
  const ws::Rig rig = source->simulator().Truth().rig;
  widestereo::stereo_frame_t frame{};
  frame.left = ws::MatToImage(pair->left, 1);
  frame.right = ws::MatToImage(pair->right, 1);

  ws::MatcherConfig live;  // config/stereo-match-live.yaml
  live.kind = "sgbm3way";
  live.downscale = 2;
  const int n = live.downscale;
  ws::RectifyOptions options;
  options.mode = ws::RectificationMode::kAuto;
  ws::DisparityMatcher full_matcher(live), coarse_matcher(ws::AtMatchScale(live));
  const auto full = ws::RectifyAndMatch(std::make_shared<const ws::Rectification>(ws::BuildRectification(rig, options)),
                                        full_matcher, frame);
  options.downscale = n;
  const auto coarse = ws::RectifyAndMatch(
      std::make_shared<const ws::Rectification>(ws::BuildRectification(rig, options)), coarse_matcher, frame);
  ASSERT_EQ(coarse.disparity.size(), cv::Size(full.disparity.cols / n, full.disparity.rows / n));
  EXPECT_DOUBLE_EQ(coarse.rect->f, full.rect->f / n);

  // Full-size remap + downscale: the coarse grid's match, scaled back to the
  // full image by nearest neighbour; its pixel (n v, n u) is coarse (v, u)'s.
  // Differences in full-resolution pixels.
  std::vector<double> differences;
  int only_full = 0, only_coarse = 0;
  for (int v = 0; v < coarse.disparity.rows; ++v)
    for (int u = 0; u < coarse.disparity.cols; ++u) {
      const float a = full.disparity.at<float>(n * v, n * u), b = n * coarse.disparity.at<float>(v, u);
      if (Valid(a) && Valid(b))
        differences.push_back(b - a);
      else
        only_full += Valid(a), only_coarse += Valid(b);
    }
  const double both = double(differences.size()), pixels = double(coarse.disparity.total());
  double mean = 0;
  for (double d : differences) mean += d / both;
  std::vector<double> absolute(differences.size());
  std::transform(differences.begin(), differences.end(), absolute.begin(), [](double d) { return std::abs(d); });
  std::sort(absolute.begin(), absolute.end());
  const double median = absolute[absolute.size() / 2], p95 = absolute[absolute.size() * 95 / 100];
  const double beyond_1px = double(absolute.end() - std::upper_bound(absolute.begin(), absolute.end(), 1.0)) / both;
  std::printf("[ resolution ] both %.4f of the pixels, only full-size %.4f, only coarse %.4f; coarse - full: "
              "mean %+.4f px, |median| %.4f px, |p95| %.4f px, beyond 1 px %.4f\n",
              both / pixels, only_full / pixels, only_coarse / pixels, mean, median, p95, beyond_1px);
  // The clouds of both (the live cloud step, 4), against the true wall.
  const ws::SimFrameTruth wall = source->simulator().Truth().frames.front();
  ws::CloudSampling sampling;
  sampling.step = 4;
  std::vector<double> rms;
  for (const auto* matched : {&full, &coarse}) {
    const auto cloud = ws::DisparityToCloud(*matched->rect, matched->disparity, 0, {}, sampling);
    const cv::Vec3d normal = matched->rect->R_left * wall.wall_normal;
    double sum = 0;
    for (const auto& p : cloud.xyz) sum += std::pow(normal.dot(cv::Vec3d(p[0], p[1], p[2])) - wall.wall_offset, 2);
    rms.push_back(std::sqrt(sum / double(cloud.xyz.size())));
    std::printf("[ resolution ] %s: %zu points, RMS to the true wall %.3f mm\n",
                matched == &full ? "full-size remap + downscale" : "remap at the matcher's resolution",
                cloud.xyz.size(), 1000 * rms.back());
  }
  EXPECT_LT(rms[1], 1.05 * rms[0]);
  EXPECT_GT(both / pixels, 0.9);
  EXPECT_LT((only_full + only_coarse) / pixels, 0.01);
  EXPECT_LT(std::abs(mean), 0.02);
  EXPECT_LT(median, 0.1);
  EXPECT_LT(beyond_1px, 0.005);
}

}  // namespace
