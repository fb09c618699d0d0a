#include "match/matcher.h"

#include <algorithm>
#include <stdexcept>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

namespace ws {
namespace {

void Require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("matcher: " + what);
}

cv::Mat Gray8(const cv::Mat& image) {
  Require(image.depth() == CV_8U, "images must be 8-bit");
  if (image.channels() == 1) return image;
  cv::Mat gray;
  cv::cvtColor(image, gray, cv::COLOR_BGR2GRAY);
  return gray;
}

// OpenCV's matchers give no disparity in the image's first columns, those
// whose whole search range (and for BM, the window's half) would not fit
// left of them: min_disparity + num_disparities (+ block_size / 2) columns.
int LeftMargin(const MatcherConfig& c) { return std::max(0, c.min_disparity + c.num_disparities) + c.block_size / 2; }

}  // namespace

MatcherConfig AtMatchScale(const MatcherConfig& c) {
  MatcherConfig scaled = c;
  const int n = c.downscale;
  scaled.downscale = 1;
  scaled.min_disparity = c.min_disparity >= 0 ? c.min_disparity / n : -((-c.min_disparity + n - 1) / n);
  scaled.num_disparities = (c.num_disparities / n + 15) / 16 * 16;
  return scaled;
}

void CheckMatcherConfig(const MatcherConfig& c) {
  Require(c.kind == "bm" || c.kind == "sgbm" || c.kind == "sgbm3way",
          "kind must be sgbm, sgbm3way or bm, not '" + c.kind + "'");
  Require(c.downscale >= 1 && c.downscale <= 8, "downscale must be 1..8");
  Require(c.num_disparities > 0 && c.num_disparities % 16 == 0,
          "num_disparities must be a positive multiple of 16");
  Require(c.block_size % 2 == 1 && c.block_size >= 1, "block_size must be odd");
  Require(c.kind != "bm" || (c.block_size >= 5 && c.block_size <= 255),
          "block_size for bm must be 5..255");
  Require(c.uniqueness_ratio >= 0 && c.speckle_window >= 0 && c.speckle_range >= 0 &&
              c.texture_threshold >= 0 && c.p1_per_pixel >= 0 && c.p2_per_pixel > c.p1_per_pixel,
          "uniqueness_ratio, speckle and texture settings must be >= 0 and p2 > p1");
}

MatcherReach Reach(const MatcherConfig& config) {
  const MatcherConfig c = AtMatchScale(config);
  const int n = config.downscale, half = c.block_size / 2;
  return {n * (std::max(0, c.min_disparity + c.num_disparities) + half), n * (std::max(0, -c.min_disparity) + half),
          n * half};
}

cv::Ptr<cv::StereoMatcher> MakeMatcher(const MatcherConfig& c) {
  CheckMatcherConfig(c);
  if (c.kind == "bm") {
    auto bm = cv::StereoBM::create(c.num_disparities, c.block_size);
    bm->setMinDisparity(c.min_disparity);
    bm->setUniquenessRatio(c.uniqueness_ratio);
    bm->setSpeckleWindowSize(c.speckle_window);
    bm->setSpeckleRange(c.speckle_range);
    bm->setTextureThreshold(c.texture_threshold);
    bm->setDisp12MaxDiff(c.disp12_max_diff);
    return bm;
  }
  const int area = c.block_size * c.block_size;
  return cv::StereoSGBM::create(c.min_disparity, c.num_disparities, c.block_size,
                                c.p1_per_pixel * area, c.p2_per_pixel * area, c.disp12_max_diff, 0,
                                c.uniqueness_ratio, c.speckle_window, c.speckle_range,
                                c.kind == "sgbm3way" ? cv::StereoSGBM::MODE_SGBM_3WAY
                                                     : cv::StereoSGBM::MODE_SGBM);
}


DisparityMatcher::DisparityMatcher(const MatcherConfig& config)
    : config_(config), matcher_(MakeMatcher(AtMatchScale(config))), margin_(LeftMargin(AtMatchScale(config))) {}

void DisparityMatcher::Match(const cv::Mat& left, const cv::Mat& right, double scale, int margin,
                             cv::Mat* disparity) {
  // Matched with `margin` columns of no image added on the left, so that the
  // image's own first columns get a disparity wherever the right image holds
  // their match; the margin is cut off again. Without one, the images
  // themselves go to the matcher: no copy.
  const bool padded = margin > 0;
  if (padded) {
    cv::copyMakeBorder(left, padded_left_, 0, 0, margin, 0, cv::BORDER_CONSTANT, cv::Scalar(0));
    cv::copyMakeBorder(right, padded_right_, 0, 0, margin, 0, cv::BORDER_CONSTANT, cv::Scalar(0));
  }
  matcher_->compute(padded ? padded_left_ : left, padded ? padded_right_ : right, fixed_point_);
  // OpenCV marks pixels without a match (min_disparity - 1) * 16.
  fixed_point_.colRange(margin, fixed_point_.cols).convertTo(*disparity, CV_32F, scale / cv::StereoMatcher::DISP_SCALE);
}

cv::Mat DisparityMatcher::Compute(const cv::Mat& left, const cv::Mat& right, int context_columns) {
  cv::Mat disparity;
  ComputeInto(left, right, &disparity, context_columns);
  return disparity;
}

void DisparityMatcher::ComputeInto(const cv::Mat& left, const cv::Mat& right, cv::Mat* out, int context_columns) {
  Require(left.size() == right.size(), "left and right images differ in size");
  Require(context_columns >= 0, "context_columns must be >= 0");
  Require(out->empty() || (out->size() == left.size() && out->type() == CV_32FC1),
          "the disparity to write into must be empty or CV_32FC1 of the images' size");
  cv::Mat& disparity = *out;
  const int n = config_.downscale;
  if (n == 1) return Match(Gray8(left), Gray8(right), 1.0, std::max(0, margin_ - context_columns), out);
  const cv::Size small((left.cols + n - 1) / n, (left.rows + n - 1) / n);
  cv::resize(Gray8(left), small_left_, small, 0, 0, cv::INTER_AREA);
  cv::resize(Gray8(right), small_right_, small, 0, 0, cv::INTER_AREA);
  Match(small_left_, small_right_, double(n), std::max(0, margin_ - context_columns / n), &small_disparity_);
  // Nearest neighbour: no disparity mixed with a missing one at an edge.
  cv::resize(small_disparity_, disparity, left.size(), 0, 0, cv::INTER_NEAREST);
  const float missing = float(config_.min_disparity - 1);
  disparity.setTo(missing, disparity < float(config_.min_disparity));
}

}  // namespace ws
