// The saddle-point fit (saddle_point.h) on an X-junction drawn at a known
// sub-pixel position, the cases where it finds nothing, what it says about
// itself (share explained, standard error), and the per-corner choice of
// scale with its fallback (corner_refinement.h).
#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "detect/corner_refinement.h"
#include "detect/saddle_point.h"

namespace {

using ws::SaddleWindow;

// Two edges crossing at `corner` at an angle (a skewed chessboard corner),
// 8 x 8 samples a pixel, pixel centres at integers, then blurred, then
// Gaussian noise of `noise` grey levels. A horizontal edge is drawn where
// it crosses between two rows of samples: at y = k / 8 - 0.5 for whole k,
// so the corners below are placed there.
cv::Mat XJunction(cv::Size size, cv::Point2d corner, double angle_deg, double blur, double noise = 0,
                  uint64_t seed = 1) {
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
  if (blur > 0) cv::GaussianBlur(image, image, cv::Size(), blur);
  if (noise > 0) {
    cv::Mat grain(size, CV_32F);
    cv::RNG(seed).fill(grain, cv::RNG::NORMAL, 0, noise);
    image += grain;
  }
  cv::Mat gray;
  image.convertTo(gray, CV_8U);
  return gray;
}

TEST(SaddlePoint, FindsASkewedCornerToAHundredthOfAPixel) {
  const SaddleWindow window(1.5);
  for (const cv::Point2d corner : {cv::Point2d(40.375, 30.625), cv::Point2d(41.5, 29.5), cv::Point2d(40.125, 30.875)})
    for (double angle : {90.0, 60.0}) {
      const cv::Mat gray = XJunction({80, 60}, corner, angle, 0.7);
      const cv::Point2f start(float(corner.x + 0.6), float(corner.y - 0.5));
      const auto fit = window.Fit(gray, start);
      ASSERT_TRUE(fit) << "corner " << corner << " angle " << angle;
      EXPECT_LT(cv::norm(cv::Point2d(fit->point) - corner), 0.01)
          << "corner " << corner << " angle " << angle << ": found " << fit->point;
    }
}

// The threshold corner_refinement.h calls a poor fit (0.75) lies below every
// ideal junction: sharp or blurred, edges crossing at 90 down to 20 degrees.
TEST(SaddlePoint, AnIdealJunctionFitsWithMostOfItsVarianceExplained) {
  const cv::Point2d corner(40.375, 30.625);
  for (double angle : {90.0, 45.0, 20.0})
    for (double blur : {0.0, 0.7, 1.5})
      for (double sigma : {1.0, 2.0, 4.0}) {
        const auto fit = SaddleWindow(sigma).Fit(XJunction({120, 100}, corner, angle, blur), cv::Point2f(corner));
        ASSERT_TRUE(fit) << angle << " " << blur << " " << sigma;
        EXPECT_GE(fit->explained, 0.85) << angle << " deg, blur " << blur << ", sigma " << sigma;
      }
}

// The standard error the fit gives for image noise is the scatter of its
// point over noise draws, within the scatter's own sampling error.
TEST(SaddlePoint, StandardErrorMatchesTheScatterOverNoiseDraws) {
  constexpr double kNoise = 8;
  constexpr int kDraws = 200;
  const cv::Point2d corner(40.375, 30.625);
  for (double sigma : {1.0, 2.0}) {
    const SaddleWindow window(sigma);
    double squared = 0, predicted = 0;
    for (int draw = 0; draw < kDraws; ++draw) {
      const auto fit = window.Fit(XJunction({80, 60}, corner, 70, 0.7, kNoise, draw + 1), cv::Point2f(corner));
      ASSERT_TRUE(fit);
      squared += std::pow(cv::norm(cv::Point2d(fit->point) - corner), 2);
      predicted += kNoise * fit->error_per_noise;
    }
    const double scatter = std::sqrt(squared / kDraws), error = predicted / kDraws;
    std::printf("sigma %.0f: scatter %.4f px, standard error %.4f px\n", sigma, scatter, error);
    EXPECT_NEAR(scatter / error, 1.0, 0.25) << "sigma " << sigma;
  }
}

TEST(SaddlePoint, FindsNothingWhereThereIsNoSaddle) {
  const SaddleWindow window(1.5);
  const cv::Point2f start(40.2f, 30.2f);
  // A flat image and a single straight edge have no saddle.
  EXPECT_FALSE(window.Fit(cv::Mat(60, 80, CV_8U, cv::Scalar(128)), start));
  cv::Mat edge(60, 80, CV_8U, cv::Scalar(40));
  edge.colRange(40, 80).setTo(200);
  EXPECT_FALSE(window.Fit(edge, start));
  // A window that would leave the image.
  EXPECT_FALSE(window.Fit(XJunction({80, 60}, {3.2, 30.4}, 90, 0.7), cv::Point2f(3.5f, 30.5f)));
}

TEST(ImageNoise, MeasuresTheNoiseBesideEdges) {
  for (double noise : {0.0, 2.0, 6.0}) {
    const cv::Mat gray = XJunction({200, 150}, {100.3, 75.6}, 80, 0.7, noise);
    const double measured = ws::ImageNoise(gray, cv::Rect(0, 0, 200, 150));
    const double expected = std::sqrt(noise * noise + 1.0 / 12);  // with the rounding
    EXPECT_NEAR(measured, expected, 0.15 * expected + 0.05) << noise;
  }
}

// On a noisy, blurred junction the chosen scales beat the smallest one
// (on a sharp one every scale is as good: the longer edges a larger window
// sees are smoothed as much); where the window holds no junction the corner
// falls back.
TEST(RefineCorners, NoisyCornersGainFromLargerScalesAndBadOnesFallBack) {
  const cv::Point2d corner(100.375, 75.625);
  double smallest = 0, chosen = 0;
  constexpr int kDraws = 40;
  for (int draw = 0; draw < kDraws; ++draw) {
    const cv::Mat gray = XJunction({200, 150}, corner, 80, 2.5, 10, draw + 1);
    const auto fit = SaddleWindow(1).Fit(gray, cv::Point2f(corner));
    ASSERT_TRUE(fit);
    smallest += std::pow(cv::norm(cv::Point2d(fit->point) - corner), 2);
    std::vector<cv::Point2f> points{cv::Point2f(corner) + cv::Point2f(0.4f, -0.3f)};
    EXPECT_EQ(ws::RefineCorners(gray, points, {60.0}, {cv::Point2f(0, 0)}), 0);
    chosen += std::pow(cv::norm(cv::Point2d(points[0]) - corner), 2);
  }
  std::printf("noisy junction: smallest scale %.4f px RMS, chosen scales %.4f px RMS\n",
              std::sqrt(smallest / kDraws), std::sqrt(chosen / kDraws));
  EXPECT_LT(chosen, 0.5 * smallest);

  cv::Mat edge(150, 200, CV_8U, cv::Scalar(40));
  edge.colRange(100, 200).setTo(200);
  std::vector<cv::Point2f> points{cv::Point2f(100.2f, 75.2f)};
  EXPECT_EQ(ws::RefineCorners(edge, points, {60.0}, {cv::Point2f(99, 74)}), 1);
  EXPECT_EQ(points[0], cv::Point2f(99, 74));
}

// A corner whose window holds no junction (here: flat grey, as inside a
// square) is not refined: no saddle fits, and cornerSubPix returns its
// whole-pixel start as it was. It is dropped with its id and counted; the
// junction's corner, refined, stays.
TEST(DropUnrefined, ACornerLeftAtWholePixelsIsDroppedAndCounted) {
  cv::Mat gray = XJunction({200, 150}, {60.375, 75.625}, 80, 0.7, 1);
  gray.colRange(120, 200).setTo(40);
  std::vector<cv::Point2f> points{cv::Point2f(61, 75), cv::Point2f(160, 75)};
  const std::vector<double> spacing{40.0, 40.0};
  std::vector<cv::Point2f> fallback = points;
  ws::CornerSubPix(gray, fallback, spacing);
  EXPECT_EQ(fallback[1], points[1]) << "cornerSubPix refuses a flat window";
  EXPECT_EQ(ws::RefineCorners(gray, points, spacing, fallback), 1);
  EXPECT_FALSE(ws::Unrefined(points[0])) << points[0];
  EXPECT_TRUE(ws::Unrefined(points[1]));

  std::vector<int> ids{7, 8};
  EXPECT_EQ(ws::DropUnrefined(ids, points), 1);
  EXPECT_EQ(ids, std::vector<int>{7});
  ASSERT_EQ(points.size(), 1u);
  EXPECT_LT(cv::norm(cv::Point2d(points[0]) - cv::Point2d(60.375, 75.625)), 0.05);
}

}  // namespace
