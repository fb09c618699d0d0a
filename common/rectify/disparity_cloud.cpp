#include "rectify/disparity_cloud.h"

#include <opencv2/imgproc.hpp>

namespace ws {

widestereo::point_cloud_t DisparityToCloud(const Rectification& rect, const cv::Mat& disparity,
                                           float min_disparity, const cv::Mat& intensity,
                                           double max_depth) {
  CV_Assert(disparity.type() == CV_32FC1);
  cv::Mat gray;
  if (!intensity.empty()) {
    CV_Assert(intensity.size() == disparity.size() && intensity.depth() == CV_8U);
    if (intensity.channels() == 3)
      cv::cvtColor(intensity, gray, cv::COLOR_BGR2GRAY);
    else
      gray = intensity;
  }
  widestereo::point_cloud_t cloud;
  cloud.frame = kLeftRectifiedFrame;
  const double fb = rect.f * rect.baseline;
  for (int v = 0; v < disparity.rows; ++v) {
    const float* d = disparity.ptr<float>(v);
    for (int u = 0; u < disparity.cols; ++u) {
      if (!(d[u] >= min_disparity && d[u] > 0)) continue;
      const double z = fb / d[u];
      if (z > max_depth) continue;
      cloud.xyz.push_back({float((u - rect.cx) * z / rect.f), float((v - rect.cy) * z / rect.f),
                           float(z)});
      if (!gray.empty()) cloud.intensity.push_back(gray.at<uint8_t>(v, u));
    }
  }
  cloud.npoints = int32_t(cloud.xyz.size());
  cloud.nintensity = int32_t(cloud.intensity.size());
  return cloud;
}

}  // namespace ws
