// The 3-D points of a disparity image, in the left rectified camera frame
// (x right, y down, z forward, metres), from the two rays of each match
// (ray_triangulation.h; pinhole: Z = f b / d, X = (u - cx) Z / f,
// Y = (v - cy) Z / f). Only valid disparities (>= min_disparity, > 0) at
// most max_depth from the camera become points; OpenCV's "missing" marker
// never does.
// step > 1 keeps every step-th pixel of every step-th row: a megapixel
// frame's full cloud is a 13 MB message, too much for a busy network. The
// step counts pixels of the full-resolution rectified image, and the cloud
// samples the same image positions at any resolution: on a grid n times
// coarser (Rectification::downscale) full-resolution pixel (U, V) lies at
// ((U + 1/2) / n - 1/2, (V + 1/2) / n - 1/2), between grid pixels. It
// becomes a point when its nearest grid pixel holds a disparity, the bilinear
// mean of the grid pixels about it that hold one within a pixel of the
// nearest's (at an edge of the image, of the field or of an object, the
// others are left out). The step is then at least n (one point per grid
// pixel at most): the cloud costs what the grid it is published at costs,
// not the full resolution.
#pragma once

#include <opencv2/core.hpp>

#include "lcm_io/point_cloud.h"
#include "rectify/rectification.h"

namespace ws {

struct CloudSampling {
  double max_depth = 20.0;  // metres from the left camera; farther points are left out
  int step = 1;             // full-resolution pixels between points, in u and in v
};

inline constexpr const char* kLeftRectifiedFrame = "left_rectified";

// `intensity` (8-bit grey or BGR, the left rectified image) may be empty.
PointCloud DisparityToCloud(const Rectification& rect, const cv::Mat& disparity,
                                           float min_disparity, const cv::Mat& intensity,
                                           const CloudSampling& sampling);

}  // namespace ws
