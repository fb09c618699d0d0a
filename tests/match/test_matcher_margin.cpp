// DisparityMatcher's left margin: columns that hold no image at the left of
// the pair (a match region's, left of the common field) serve as the margin
// instead of columns added to both images, and the field right of them gets
// the disparities it gets with the margin added.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include "match/matcher.h"

namespace {

TEST(MatcherMargin, ColumnsWithoutImageServeAsTheMarginAndTheFieldKeepsItsDisparities) {
  ws::MatcherConfig config;
  config.kind = "sgbm3way";
  config.num_disparities = 32;
  const int width = 320, height = 120, shift = 9;
  // The field starts after `context` columns holding no image (0), as a
  // region grown by the matcher's reach left of the common field.
  const int context = config.num_disparities + config.block_size / 2;
  cv::Mat texture(height, width + shift, CV_8UC1);
  cv::randu(texture, 0, 256);
  cv::Mat left = cv::Mat::zeros(height, width, CV_8UC1), right = cv::Mat::zeros(height, width, CV_8UC1);
  texture.colRange(context, width).copyTo(left.colRange(context, width));
  texture.colRange(context + shift, width + shift).copyTo(right.colRange(context, width));  // left x: right x - shift

  ws::DisparityMatcher matcher(config);
  const cv::Mat padded = matcher.Compute(left, right);
  const cv::Mat in_place = matcher.Compute(left, right, context);
  ASSERT_EQ(in_place.size(), padded.size());
  // The field where the whole search lies in the right image's texture.
  const cv::Rect field(context + config.num_disparities, 0, width - context - config.num_disparities, height);
  const cv::Mat same = padded(field) == in_place(field);
  EXPECT_GE(cv::countNonZero(same), 0.99 * field.area());
  const cv::Mat at_shift = cv::abs(in_place(field) - shift) < 0.5;
  EXPECT_GE(cv::countNonZero(at_shift), 0.9 * field.area());

  // Into a view of a larger image: written there, the rest untouched.
  cv::Mat whole(height + 2, width + 4, CV_32FC1, cv::Scalar(-7));
  cv::Mat view = whole(cv::Rect(3, 1, width, height));
  matcher.ComputeInto(left, right, &view, context);
  EXPECT_EQ(view.data, whole.ptr(1) + 3 * sizeof(float)) << "reallocated";
  EXPECT_EQ(cv::countNonZero(view != in_place), 0);
  EXPECT_EQ(cv::countNonZero(whole.row(0) != -7), 0);
}

}  // namespace
