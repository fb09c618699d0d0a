#include "view/disparity_colour.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include <opencv2/imgproc.hpp>

#include "lcm_io/image_codec.h"

namespace ws::view {
namespace {

// OpenCV's turbo colour map as a 256-entry table.
const cv::Mat& Turbo() {
  static const cv::Mat table = [] {
    cv::Mat ramp(1, 256, CV_8U), colours;
    for (int i = 0; i < 256; ++i) ramp.at<uint8_t>(i) = uint8_t(i);
    cv::applyColorMap(ramp, colours, cv::COLORMAP_TURBO);
    return colours;
  }();
  return table;
}

int Level(const DisparityLegend& legend, double d) {
  const double t = (d - legend.min_disparity) / (legend.max_disparity - legend.min_disparity);
  return std::isfinite(t) ? int(std::lround(255 * std::clamp(t, 0.0, 1.0))) : 0;
}

}  // namespace

double DisparityMetres(const widestereo::disparity_t& msg, double d) {
  if (!(d > 0)) return std::numeric_limits<double>::infinity();
  if (msg.rectification == widestereo::disparity_t::RECTIFICATION_LATLON)
    return msg.baseline / std::tan(d / msg.f);
  return msg.f * msg.baseline / d;
}

DisparityLegend MakeLegend(const widestereo::disparity_t& msg, int nticks) {
  DisparityLegend legend;
  legend.min_disparity = msg.min_disparity;
  legend.max_disparity = double(msg.min_disparity) + msg.num_disparities;
  // The far end: the smallest positive disparity of the scale (d = 0 is at infinity).
  const double far = std::max(legend.min_disparity, 1.0);
  for (int i = 0; i < nticks; ++i) {
    const double d = far + (legend.max_disparity - far) * i / std::max(1, nticks - 1);
    legend.ticks.push_back({d, DisparityMetres(msg, d), DisparityColour(legend, d)});
  }
  return legend;
}

cv::Vec3b DisparityColour(const DisparityLegend& legend, double d) {
  return Turbo().at<cv::Vec3b>(Level(legend, d));
}

cv::Mat ColourDisparity(const cv::Mat& disparity, const DisparityLegend& legend) {
  CV_Assert(disparity.type() == CV_32F);
  cv::Mat colour(disparity.size(), CV_8UC3, cv::Scalar::all(0));
  for (int y = 0; y < disparity.rows; ++y) {
    const float* d = disparity.ptr<float>(y);
    auto* out = colour.ptr<cv::Vec3b>(y);
    for (int x = 0; x < disparity.cols; ++x)
      if (std::isfinite(d[x]) && d[x] >= legend.min_disparity) out[x] = DisparityColour(legend, d[x]);
  }
  return colour;
}

cv::Mat WithLegend(const cv::Mat& colour, const DisparityLegend& legend) {
  const int bar = 20, text = 22, margin = 30;
  cv::Mat out(colour.rows + bar + text + 4, colour.cols, CV_8UC3, cv::Scalar::all(255));
  colour.copyTo(out(cv::Rect(0, 0, colour.cols, colour.rows)));
  const int x0 = margin, x1 = std::max(x0 + 1, colour.cols - margin);
  auto x_of = [&](double d) {
    return x0 + int(std::lround((x1 - x0) * (d - legend.min_disparity) /
                                (legend.max_disparity - legend.min_disparity)));
  };
  for (int x = x0; x <= x1; ++x) {
    const double d = legend.min_disparity + (legend.max_disparity - legend.min_disparity) * (x - x0) / (x1 - x0);
    cv::line(out, {x, colour.rows + 2}, {x, colour.rows + 2 + bar}, cv::Scalar(DisparityColour(legend, d)));
  }
  for (const LegendTick& tick : legend.ticks) {
    char label[32];
    std::snprintf(label, sizeof label, "%.2f m", tick.metres);
    const int x = x_of(tick.disparity);
    cv::line(out, {x, colour.rows + 2 + bar - 4}, {x, colour.rows + 2 + bar + 3}, cv::Scalar::all(0));
    cv::putText(out, label, {std::max(0, x - 24), colour.rows + bar + text}, cv::FONT_HERSHEY_SIMPLEX, 0.4,
                cv::Scalar::all(0), 1, cv::LINE_AA);
  }
  return out;
}

}  // namespace ws::view
