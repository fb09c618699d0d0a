// A match's 3-D point from its two rays, for every rectification mode
// (rectification.h). In the left rectified frame the left camera is at the
// origin and the right one at c = (baseline, 0, 0); the left ray through
// rectified pixel (u, v) and the right ray through (u - d, v) lie in one
// epipolar plane (the same row), so they meet at
//   X = s r_l,   s = ((c x r_r) . (r_l x r_r)) / |r_l x r_r|^2,
// r_l, r_r the rectified rays (RectifiedRay). For a pinhole rectification
// this is Z = f b / d, X = (u - cx) Z / f, Y = (v - cy) Z / f; for lat-lon
// the range |X| = b cos(psi_r) / sin(psi_l - psi_r), psi = (u - cx) / f
// (computed so).
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

// Range accuracy: how far the point of left rectified pixel (u, v) at
// disparity d moves along its ray (metres) when the disparity is off by
// `error` pixels, to first order. In the epipolar plane the triangle of the
// two cameras and the point has the angle psi_l - psi_r at the point, so
//   r = b cos(psi_r) / sin(psi_l - psi_r),   dr/dpsi_r = b cos(psi_l) / sin^2(psi_l - psi_r),
// psi the ray's angle within the plane from the plane's normal to the
// baseline, psi = asin(x / |ray|). A disparity error moves the right pixel,
// and its angle by dpsi/du at (u - d, v):
//   lat-lon: 1 / f;
//   pinhole: (1 / f) w / (w^2 + a^2), a = (u - cx) / f, w^2 = 1 + ((v - cy) / f)^2
//   (at the centre row this is Z = f b / d's dZ = Z^2 / (f b) per pixel).
// So |dr| = b cos(psi_l) / sin^2(psi_l - psi_r) * dpsi/du * error; in
// lat-lon, r^2 cos(psi_l) error / (f b cos^2 psi_r). NaN where d <= 0.
double RangeChange(const Rectification& rect, double u, double v, double d, double error = 0.1);

}  // namespace ws
