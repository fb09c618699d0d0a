// A match's 3-D point from its two rays, for every rectification mode
// (rectification.h). In the left rectified frame the left camera is at the
// origin and the right one at c = (baseline, 0, 0); the left ray through
// rectified pixel (u, v) and the right ray through (u - d, v) lie in one
// epipolar plane (the same row), so they meet at
//   X = s r_l,   s = ((c x r_r) . (r_l x r_r)) / |r_l x r_r|^2,
// r_l, r_r the rectified rays (RectifiedRay). For a pinhole rectification
// this is Z = f b / d, X = (u - cx) Z / f, Y = (v - cy) Z / f; for lat-lon
// the range |X| = b cos(psi_r) / sin(psi_l - psi_r), psi = (u - cx) / f.
#pragma once

#include <optional>

#include <opencv2/core.hpp>

#include "rectify/rectification.h"

namespace ws {

// The point of left rectified pixel (u, v) at disparity d (pixels), or
// nullopt when the rays do not meet in front of both cameras (d <= 0, or
// parallel rays).
std::optional<cv::Vec3d> TriangulateDisparity(const Rectification& rect, double u, double v,
                                              double d);

}  // namespace ws
