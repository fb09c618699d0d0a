// The largest pixel distance between a camera's projection of points and
// cv::fisheye::projectPoints' with K and D: how the kb4 tests check that the
// model is cv::fisheye's (ADD_FAILURE, and infinity, where the camera has no
// projection).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <opencv2/calib3d.hpp>

#include "models/camera_model.h"

namespace ws::test {

inline double WorstGapToOpenCvFisheye(const Camera& camera, const std::vector<cv::Point3d>& points,
                                      cv::InputArray K, cv::InputArray D) {
  std::vector<cv::Point2d> opencv;
  cv::fisheye::projectPoints(points, opencv, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), K, D);
  double worst = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    const auto pixel = camera.Project({points[i].x, points[i].y, points[i].z});
    if (!pixel) {
      ADD_FAILURE() << "no projection of point " << i;
      return std::numeric_limits<double>::infinity();
    }
    worst = std::max(worst, std::hypot(pixel->x() - opencv[i].x, pixel->y() - opencv[i].y));
  }
  return worst;
}

}  // namespace ws::test
