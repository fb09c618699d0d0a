// Dense stereo matching on rectified pairs: OpenCV's block matching (the
// paper used a 33x33 window) or semi-global block matching, either with its
// full 8 paths (sgbm) or its parallel 3-way variant (sgbm3way: uses every
// core, about half of sgbm's time on two). With downscale N the pair is
// matched at 1/N resolution (num_disparities / N, rounded up to a multiple of
// 16) and the disparities are scaled back to the full image: about N^2 less
// work, paid in depth resolution and in thin structures.
#pragma once

#include <string>

#include <opencv2/calib3d.hpp>

namespace ws {

struct MatcherConfig {
  std::string kind = "sgbm";   // "sgbm", "sgbm3way" or "bm"
  int downscale = 1;           // match at 1/downscale resolution
  int min_disparity = 0;
  int num_disparities = 128;   // a positive multiple of 16
  int block_size = 7;          // odd; BM: 5..255 (the paper: 33)
  int uniqueness_ratio = 10;
  int speckle_window = 100;
  int speckle_range = 2;
  int texture_threshold = 10;  // BM only
  int p1_per_pixel = 8;        // SGBM: P1 = p1_per_pixel * channels * block_size^2
  int p2_per_pixel = 32;       // SGBM: P2 likewise
  int disp12_max_diff = 1;
  // Match only the box of the rectified images where both hold image
  // (match/match_region.h), not the empty borders about it.
  bool common_field_only = true;
};

// The same settings for images already at 1/downscale resolution (a
// rectification with RectifyOptions::downscale): downscale 1, the disparity
// range in their pixels (num_disparities / N rounded up to a multiple of 16).
MatcherConfig AtMatchScale(const MatcherConfig& config);

// Throws std::invalid_argument naming the field when a value is out of range.
void CheckMatcherConfig(const MatcherConfig& config);

// The matcher of a config, made once and used frame after frame: OpenCV's
// matchers keep their work buffers between calls (a fresh SGBM per 1280 x 960
// frame costs its allocation every time). Not for several threads at once.
class DisparityMatcher {
 public:
  // Throws std::invalid_argument like CheckMatcherConfig.
  explicit DisparityMatcher(const MatcherConfig& config);

  // Disparity in pixels of the full images (CV_32FC1) of two rectified 8-bit
  // images (grey or BGR, converted to grey); pixels without a match hold
  // min_disparity - 1. Every column may get one: the images are matched with
  // a margin of no image on the left as wide as the search range, where
  // OpenCV's matchers would give none. The images' first context_columns
  // need no disparity of their own (they hold no image, as a match region's
  // columns left of the common field: match/match_region.h): they serve as
  // that margin, and only the part of it they do not cover is added, so
  // that no column is matched for nothing. Their disparities are not to be
  // used.
  cv::Mat Compute(const cv::Mat& left, const cv::Mat& right, int context_columns = 0);
  // As Compute, into *disparity: a Mat of left's size and CV_32FC1 (a view
  // into a larger image, say) is written in place, not reallocated.
  void ComputeInto(const cv::Mat& left, const cv::Mat& right, cv::Mat* disparity, int context_columns = 0);

  const MatcherConfig& config() const { return config_; }

 private:
  // The match of two 8-bit grey images at the matcher's scale, times
  // `scale`, with `margin` columns of no image added on the left.
  void Match(const cv::Mat& left, const cv::Mat& right, double scale, int margin, cv::Mat* disparity);

  MatcherConfig config_;
  cv::Ptr<cv::StereoMatcher> matcher_;
  int margin_;  // columns added on the left (LeftMargin)
  cv::Mat fixed_point_, small_left_, small_right_, small_disparity_, padded_left_, padded_right_;
};

// How far the match of a pixel reads, in full-resolution pixels: the columns
// to its left (the disparity search, which must fit in the image for the
// pixel to get a disparity, and half a window), to its right (negative
// disparities, half a window) and the rows above and below (half a window).
struct MatcherReach {
  int left = 0, right = 0, rows = 0;
};
MatcherReach Reach(const MatcherConfig& config);

// The raw OpenCV matcher for `config` at full resolution (downscale is
// DisparityMatcher's), for comparisons with bare OpenCV.
cv::Ptr<cv::StereoMatcher> MakeMatcher(const MatcherConfig& config);

}  // namespace ws
