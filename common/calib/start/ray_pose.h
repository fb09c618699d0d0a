// The pose of a plane board from the rays of its corners, for cameras whose
// rays may leave the pinhole's half space (fisheye, beyond 90 degrees).
//
// The direct linear transform of a homography (Hartley & Zisserman, Alg. 4.2)
// written on unit rays d_i instead of homogeneous pixels: d_i x (H m_i) = 0,
// m_i = (X_i, Y_i, 1), H = lambda [r1 r2 t]. A ray is a direction in any
// half space, so the constraint holds at every incidence angle; the sign of
// lambda puts H m_i along d_i (not against it). The generalised camera
// literature solves planar PnP the same way (e.g. Scaramuzza, Martinelli &
// Siegwart 2006, Sec. 3, for the board pose of an omnidirectional camera).
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "calib/solver/pose.h"

namespace ws::calib {

// Board -> camera pose with R (board plane z = 0) and t; nullopt for fewer
// than 4 points, a board point off the plane z = 0, or a degenerate set.
std::optional<Pose> PoseFromRays(const std::vector<Eigen::Vector3d>& object,
                                 const std::vector<Eigen::Vector3d>& rays);

}  // namespace ws::calib
