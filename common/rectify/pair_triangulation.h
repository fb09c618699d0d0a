// A point from a match of raw (not rectified) pixels: the left pixel's ray
// from the left camera's centre and the right pixel's from the right one's
// (c = -R^T T in the left frame, X_right = R X_left + T) meet, or pass
// closest, at
//   s r_l  and  c + t R^T r_r,   [s t] the least-squares solution of s r_l - t R^T r_r = c,
// and the point is the midpoint of the two.
#pragma once

#include <optional>

#include <Eigen/Core>

#include "models/camera_model.h"

namespace ws {

// The point in the left camera's frame (metres); nullopt when either pixel
// has no ray, the rays are parallel, or the point lies behind either camera
// (s <= 0 or t <= 0).
std::optional<Eigen::Vector3d> TriangulatePixels(const Camera& left, const Camera& right,
                                                 const Eigen::Matrix3d& R, const Eigen::Vector3d& T,
                                                 const Eigen::Vector2d& left_pixel,
                                                 const Eigen::Vector2d& right_pixel);

}  // namespace ws
