#include "rectify/disparity_cloud.h"

#include <algorithm>
#include <iterator>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "rectify/ray_triangulation.h"

namespace ws {
namespace {

// The points of rows [begin, end), appended to `cloud` (xyz and, when `gray`
// is not empty, intensity).
void RowsToPoints(const Rectification& rect, const cv::Mat& disparity, float min_disparity,
                  const cv::Mat& gray, const CloudSampling& sampling, int step, int begin, int end,
                  widestereo::point_cloud_t* cloud) {
  for (int v = begin; v < end; ++v) {
    if (v % step != 0) continue;
    const float* d = disparity.ptr<float>(v);
    for (int u = 0; u < disparity.cols; u += step) {
      if (!(d[u] >= min_disparity && d[u] > 0)) continue;
      const auto X = TriangulateDisparity(rect, u, v, d[u]);
      if (!X || cv::norm(*X) > sampling.max_depth) continue;
      cloud->xyz.push_back({float((*X)[0]), float((*X)[1]), float((*X)[2])});
      if (!gray.empty()) cloud->intensity.push_back(gray.at<uint8_t>(v, u));
    }
  }
}

}  // namespace

widestereo::point_cloud_t DisparityToCloud(const Rectification& rect, const cv::Mat& disparity,
                                           float min_disparity, const cv::Mat& intensity,
                                           const CloudSampling& sampling) {
  CV_Assert(disparity.type() == CV_32FC1 && sampling.step >= 1);
  cv::Mat gray;
  if (!intensity.empty()) {
    CV_Assert(intensity.size() == disparity.size() && intensity.depth() == CV_8U);
    if (intensity.channels() == 3)
      cv::cvtColor(intensity, gray, cv::COLOR_BGR2GRAY);
    else
      gray = intensity;
  }
  const int step = std::max(1, sampling.step / rect.downscale);
  // A megapixel frame gives a million points, each its own small array in
  // point_cloud_t: bands of rows are converted on every core, then moved
  // into the message in row order.
  constexpr int kBandRows = 32;
  const int bands = (disparity.rows + kBandRows - 1) / kBandRows;
  std::vector<widestereo::point_cloud_t> parts(static_cast<size_t>(bands));
  cv::parallel_for_(cv::Range(0, bands), [&](const cv::Range& range) {
    for (int band = range.start; band < range.end; ++band)
      RowsToPoints(rect, disparity, min_disparity, gray, sampling, step, band * kBandRows,
                   std::min(disparity.rows, (band + 1) * kBandRows), &parts[size_t(band)]);
  });
  widestereo::point_cloud_t cloud;
  cloud.frame = kLeftRectifiedFrame;
  size_t total = 0;
  for (const auto& part : parts) total += part.xyz.size();
  cloud.xyz.reserve(total);
  cloud.intensity.reserve(gray.empty() ? 0 : total);
  for (auto& part : parts) {
    std::move(part.xyz.begin(), part.xyz.end(), std::back_inserter(cloud.xyz));
    cloud.intensity.insert(cloud.intensity.end(), part.intensity.begin(), part.intensity.end());
  }
  cloud.npoints = int32_t(cloud.xyz.size());
  cloud.nintensity = int32_t(cloud.intensity.size());
  return cloud;
}

}  // namespace ws
