// The saddle-point refinement (saddle_point.h) on an X-junction drawn at a
// known sub-pixel position, and the cases where it must leave the start.
#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "detect/saddle_point.h"

namespace {

using ws::SaddlePoint;

// Two edges crossing at `corner` at an angle (a skewed chessboard corner),
// 8 x 8 samples a pixel, pixel centres at integers, then blurred. A
// horizontal edge is drawn where it crosses between two rows of samples:
// at y = k / 8 - 0.5 for whole k, so the corners below are placed there.
cv::Mat XJunction(cv::Size size, cv::Point2d corner, double angle_deg, double blur) {
  const cv::Point2d a(1, 0), b(std::cos(angle_deg * M_PI / 180), std::sin(angle_deg * M_PI / 180));
  cv::Mat image(size, CV_32F);
  constexpr int n = 8;
  for (int y = 0; y < size.height; ++y)
    for (int x = 0; x < size.width; ++x) {
      double sum = 0;
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          const cv::Point2d p = cv::Point2d(x - 0.5 + (i + 0.5) / n, y - 0.5 + (j + 0.5) / n) - corner;
          const double side_a = a.x * p.y - a.y * p.x, side_b = b.x * p.y - b.y * p.x;
          sum += side_a * side_b > 0 ? 200 : 40;
        }
      image.at<float>(y, x) = float(sum / (n * n));
    }
  cv::GaussianBlur(image, image, cv::Size(), blur);
  cv::Mat gray;
  image.convertTo(gray, CV_8U);
  return gray;
}

TEST(SaddlePoint, FindsASkewedCornerToAHundredthOfAPixel) {
  for (const cv::Point2d corner : {cv::Point2d(40.375, 30.625), cv::Point2d(41.5, 29.5), cv::Point2d(40.125, 30.875)})
    for (double angle : {90.0, 60.0}) {
      const cv::Mat gray = XJunction({80, 60}, corner, angle, 0.7);
      const cv::Point2f start(float(corner.x + 0.6), float(corner.y - 0.5));
      const cv::Point2f found = SaddlePoint(gray, start, 1.5);
      EXPECT_LT(cv::norm(cv::Point2d(found) - corner), 0.01)
          << "corner " << corner << " angle " << angle << ": found " << found;
    }
}

TEST(SaddlePoint, LeavesTheStartWhereThereIsNoSaddle) {
  const cv::Point2f start(40.2f, 30.2f);
  // A flat image and a single straight edge have no saddle.
  EXPECT_EQ(SaddlePoint(cv::Mat(60, 80, CV_8U, cv::Scalar(128)), start, 1.5), start);
  cv::Mat edge(60, 80, CV_8U, cv::Scalar(40));
  edge.colRange(40, 80).setTo(200);
  EXPECT_EQ(SaddlePoint(edge, start, 1.5), start);
  // A window that would leave the image.
  const cv::Mat gray = XJunction({80, 60}, {3.2, 30.4}, 90, 0.7);
  EXPECT_EQ(SaddlePoint(gray, cv::Point2f(3.5f, 30.5f), 1.5), cv::Point2f(3.5f, 30.5f));
}

}  // namespace
