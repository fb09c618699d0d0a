// The disparity's colours and legend: each tick's metres are the disparity's
// distance by the message's own geometry, and its colour is the one a pixel
// of that disparity gets.
#include <gtest/gtest.h>

#include <cmath>

#include "lcm_io/image_codec.h"
#include "view/disparity_colour.h"

namespace {

using namespace ws::view;

widestereo::disparity_t Disparity(const cv::Mat& d, int8_t rectification) {
  widestereo::disparity_t msg{};
  msg.disparity = ws::MatToImage(d, 1);
  msg.min_disparity = 0;
  msg.num_disparities = 64;
  msg.rectification = rectification;
  msg.f = 500;
  msg.cx = d.cols / 2.0;
  msg.cy = d.rows / 2.0;
  msg.baseline = 0.12;
  return msg;
}

TEST(DisparityColour, LegendTicksGiveTheDistanceAndTheColourOfTheirDisparity) {
  cv::Mat d(4, 64, CV_32F);
  for (int x = 0; x < 64; ++x) d.col(x).setTo(float(x));
  d.at<float>(0, 0) = -1;  // no disparity
  const auto msg = Disparity(d, widestereo::disparity_t::RECTIFICATION_PINHOLE);
  const DisparityLegend legend = MakeLegend(msg);
  ASSERT_EQ(legend.ticks.size(), 5u);
  EXPECT_EQ(legend.min_disparity, 0);
  EXPECT_EQ(legend.max_disparity, 64);
  const cv::Mat colour = ColourDisparity(d, legend);
  EXPECT_EQ(colour.at<cv::Vec3b>(0, 0), cv::Vec3b(0, 0, 0));
  for (const LegendTick& tick : legend.ticks) {
    EXPECT_NEAR(tick.metres, 500 * 0.12 / tick.disparity, 1e-12);
    if (tick.disparity == std::floor(tick.disparity) && tick.disparity < 64) {
      EXPECT_EQ(colour.at<cv::Vec3b>(1, int(tick.disparity)), tick.bgr) << tick.disparity;
    }
  }
  EXPECT_GT(legend.ticks.front().metres, legend.ticks.back().metres);  // far to near
  EXPECT_NE(legend.ticks.front().bgr, legend.ticks.back().bgr);
  const cv::Mat shown = WithLegend(colour, legend);
  EXPECT_EQ(shown.cols, colour.cols);
  EXPECT_GT(shown.rows, colour.rows);
}

TEST(DisparityColour, LatLonMetresAreTheRangeStraightAhead) {
  const auto msg = Disparity(cv::Mat(4, 8, CV_32F, cv::Scalar(10)), widestereo::disparity_t::RECTIFICATION_LATLON);
  // psi_l = 0, psi_r = -d / f: range = baseline cos(psi_r) / sin(psi_l - psi_r).
  EXPECT_NEAR(DisparityMetres(msg, 10), 0.12 * std::cos(10.0 / 500) / std::sin(10.0 / 500), 1e-12);
  EXPECT_TRUE(std::isinf(DisparityMetres(msg, 0)));
}

}  // namespace
