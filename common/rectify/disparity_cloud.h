// The 3-D points of a disparity image, in the left rectified camera frame
// (x right, y down, z forward, metres), from the two rays of each match
// (ray_triangulation.h; pinhole: Z = f b / d, X = (u - cx) Z / f,
// Y = (v - cy) Z / f). Only valid disparities (>= min_disparity, > 0) at
// most max_depth from the camera become points; OpenCV's "missing" marker
// never does.
// step > 1 keeps every step-th pixel of every step-th row: a megapixel
// frame's full cloud is a 13 MB message, too much for a busy network. The
// step counts pixels of the full-resolution rectified image: on a grid n
// times coarser (Rectification::downscale) it is step / n of its pixels (at
// least 1), so the cloud is built at the resolution it is published at.
#pragma once

#include <opencv2/core.hpp>

#include "rectify/rectification.h"
#include "widestereo/point_cloud_t.hpp"

namespace ws {

struct CloudSampling {
  double max_depth = 20.0;  // metres from the left camera; farther points are left out
  int step = 1;             // full-resolution pixels between points, in u and in v
};

inline constexpr const char* kLeftRectifiedFrame = "left_rectified";

// `intensity` (8-bit grey or BGR, the left rectified image) may be empty.
widestereo::point_cloud_t DisparityToCloud(const Rectification& rect, const cv::Mat& disparity,
                                           float min_disparity, const cv::Mat& intensity,
                                           const CloudSampling& sampling);

}  // namespace ws
