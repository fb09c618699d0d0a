#include "rectify/disparity_cloud.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "rectify/ray_triangulation.h"

namespace ws {
namespace {

// Neighbouring disparities further apart than this (grid pixels) are not
// interpolated between: an edge, not a slope.
constexpr float kMaxSpread = 1.0f;

bool Valid(float d, float min_disparity) { return d >= min_disparity && d > 0; }

// Where the full-resolution pixels 0, step, 2 step, ... of an axis of
// `full` pixels lie on a grid n times coarser: full-resolution pixel U is
// at (U + 1/2) / n - 1/2 of the grid (rectification.h: grid pixel u'
// covers the n full-resolution pixels about n u' + (n - 1) / 2).
std::vector<double> Positions(int full, int n, int step) {
  std::vector<double> x;
  for (int U = 0; U < full; U += step) x.push_back((U + 0.5) / n - 0.5);
  return x;
}

// The disparity (and intensity) at grid position (x, y): whether there is a
// point there is its nearest grid pixel's to say (it holds a disparity); its
// value is the bilinear mean of the grid pixels about (x, y) that hold one
// within kMaxSpread of the nearest's (all of them but at an edge of the
// image, of the matched field or of an object, where the others are left
// out). False when the nearest grid pixel holds none.
bool SampleAt(const cv::Mat& disparity, const cv::Mat& gray, float min_disparity, double x, double y,
              float* d, float* intensity) {
  const cv::Point nearest(std::clamp(int(std::lround(x)), 0, disparity.cols - 1),
                          std::clamp(int(std::lround(y)), 0, disparity.rows - 1));
  const float dn = disparity.at<float>(nearest);
  if (!Valid(dn, min_disparity)) return false;
  if (nearest.x == x && nearest.y == y) {  // on a grid pixel (the full-resolution grid): its own
    *d = dn;
    *intensity = gray.empty() ? 0.f : float(gray.at<uint8_t>(nearest));
    return true;
  }
  const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  const double ax = x - x0, ay = y - y0;
  const std::array<double, 4> w = {(1 - ax) * (1 - ay), ax * (1 - ay), (1 - ax) * ay, ax * ay};
  const std::array<cv::Point, 4> p = {cv::Point(x0, y0), cv::Point(x0 + 1, y0), cv::Point(x0, y0 + 1),
                                      cv::Point(x0 + 1, y0 + 1)};
  const cv::Rect inside(0, 0, disparity.cols, disparity.rows);
  double sum_w = 0, sum_d = 0, sum_g = 0;
  for (int k = 0; k < 4; ++k) {
    if (w[k] == 0 || !inside.contains(p[k])) continue;
    const float dk = disparity.at<float>(p[k]);
    if (!Valid(dk, min_disparity) || std::abs(dk - dn) > kMaxSpread) continue;
    sum_w += w[k];
    sum_d += w[k] * dk;
    if (!gray.empty()) sum_g += w[k] * gray.at<uint8_t>(p[k]);
  }
  if (sum_w == 0) return false;  // not reached: the nearest is one of the four
  *d = float(sum_d / sum_w);
  *intensity = float(sum_g / sum_w);
  return true;
}

// The points of sampled rows [begin, end), appended to `cloud` (xyz and,
// when `gray` is not empty, intensity).
void RowsToPoints(const Rectification& rect, const cv::Mat& disparity, float min_disparity,
                  const cv::Mat& gray, const CloudSampling& sampling, const std::vector<double>& xs,
                  const std::vector<double>& ys, int begin, int end, PointCloud* cloud) {
  for (int j = begin; j < end; ++j)
    for (double x : xs) {
      float d, intensity;
      if (!SampleAt(disparity, gray, min_disparity, x, ys[size_t(j)], &d, &intensity)) continue;
      const auto X = TriangulateDisparity(rect, x, ys[size_t(j)], d);
      if (!X || cv::norm(*X) > sampling.max_depth) continue;
      cloud->xyz.push_back({float((*X)[0]), float((*X)[1]), float((*X)[2])});
      if (!gray.empty()) cloud->intensity.push_back(uint8_t(std::lround(intensity)));
    }
}

}  // namespace

PointCloud DisparityToCloud(const Rectification& rect, const cv::Mat& disparity,
                                           float min_disparity, const cv::Mat& intensity,
                                           const CloudSampling& sampling) {
  CV_Assert(disparity.type() == CV_32FC1 && sampling.step >= 1 && rect.downscale >= 1);
  cv::Mat gray;
  if (!intensity.empty()) {
    CV_Assert(intensity.size() == disparity.size() && intensity.depth() == CV_8U);
    if (intensity.channels() == 3)
      cv::cvtColor(intensity, gray, cv::COLOR_BGR2GRAY);
    else
      gray = intensity;
  }
  // The full-resolution pixels (step i, step j), as a full-size disparity
  // would give them; on a coarser grid a step of at least one grid pixel,
  // so that the cloud costs no more than the grid it is published at.
  const int n = rect.downscale, step = std::max(sampling.step, n);
  const std::vector<double> xs = Positions(disparity.cols * n, n, step);
  const std::vector<double> ys = Positions(disparity.rows * n, n, step);
  // A megapixel frame gives a million points: bands of rows are converted
  // on every core, then copied into the message in row order.
  const int rows = int(ys.size());
  const int band_rows = std::max(1, 32 / step);
  const int bands = (rows + band_rows - 1) / band_rows;
  std::vector<PointCloud> parts(static_cast<size_t>(bands));
  cv::parallel_for_(cv::Range(0, bands), [&](const cv::Range& range) {
    for (int band = range.start; band < range.end; ++band)
      RowsToPoints(rect, disparity, min_disparity, gray, sampling, xs, ys, band * band_rows,
                   std::min(rows, (band + 1) * band_rows), &parts[size_t(band)]);
  });
  PointCloud cloud;
  cloud.frame = kLeftRectifiedFrame;
  size_t total = 0;
  for (const auto& part : parts) total += part.xyz.size();
  cloud.xyz.reserve(total);
  cloud.intensity.reserve(gray.empty() ? 0 : total);
  for (const auto& part : parts) {
    cloud.xyz.insert(cloud.xyz.end(), part.xyz.begin(), part.xyz.end());
    cloud.intensity.insert(cloud.intensity.end(), part.intensity.begin(), part.intensity.end());
  }
  cloud.npoints = int32_t(cloud.xyz.size());
  cloud.nintensity = int32_t(cloud.intensity.size());
  return cloud;
}

}  // namespace ws
