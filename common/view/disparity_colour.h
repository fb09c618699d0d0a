// The disparity as a colour image with a legend in metres: stereo-match
// --save-disparity writes it as PNG, stereo-view shows it. Colours run over
// the matcher's search range (disparity_t's min_disparity to min_disparity +
// num_disparities), turbo from far (blue) to near (red); pixels without a
// disparity (below min_disparity, or not finite) are black.
#pragma once

#include <vector>

#include <opencv2/core.hpp>

#include "widestereo/disparity_t.hpp"

namespace ws::view {

// The distance of a disparity d > 0 straight ahead (+infinity for d <= 0):
// pinhole Z = f baseline / d; lat-lon the range at psi_l = 0,
// baseline / tan(d / f) (disparity_t's formulas).
double DisparityMetres(const widestereo::disparity_t& msg, double d);

struct LegendTick {
  double disparity;  // pixels
  double metres;     // DisparityMetres of it
  cv::Vec3b bgr;     // its colour
};

struct DisparityLegend {
  double min_disparity = 0, max_disparity = 1;  // the colour scale's ends
  std::vector<LegendTick> ticks;                // from far to near
};

DisparityLegend MakeLegend(const widestereo::disparity_t& msg, int nticks = 5);
// The colour of disparity d on the legend's scale.
cv::Vec3b DisparityColour(const DisparityLegend& legend, double d);
// Every pixel of a CV_32F disparity image in its colour (CV_8UC3, BGR).
cv::Mat ColourDisparity(const cv::Mat& disparity, const DisparityLegend& legend);
// `colour` with the legend drawn below it: the colour bar and each tick's metres.
cv::Mat WithLegend(const cv::Mat& colour, const DisparityLegend& legend);

}  // namespace ws::view
