// What keeps a calibrated non-radial field (models/nonradial_field.h)
// identifiable: a prior on its coefficients c, residuals in pixels,
//
//   e = fx [ lambda c ;  lambda D2 c ;  w_g A c ].
//
// - The gauge, A c = 0 (weight w_g = kGaugeWeight): first-order changes of
//   fx, fy, cx, cy, p1, p2, every radial coefficient and the camera's
//   rotation (all board poses turned together) move the distorted point by
//   fields of their own, g_k(x_d). A field F with a part in their span could
//   hand it to them and project the same: the data cannot tell. So F is
//   held orthogonal to that span over a grid of samples of the field's
//   rectangle (2 cols x 2 rows cell centres, those the radial model
//   inverts): A = U^T B, U an orthonormal basis of the patterns g_k at the
//   samples, B the field's values there. The radial curve, focal lengths,
//   principal point and poses keep what they describe; F only what they
//   cannot. The patterns are those at the camera the field is added to.
// - Smoothness, lambda D2 c: the second differences of the control points
//   along rows and columns, each component, as for the radial spline
//   (smoothness_prior.h): they decide the cells no corner reaches.
// - Size, lambda c: a weak pull of every coefficient towards 0, so that
//   a control point beyond every corner stays near no correction.
// lambda, chosen with the field by held-out error (options.h,
// kFieldSmoothnessLadder): a field that moves a corner by 1 px costs as much
// as a corner lambda px off.
#pragma once

#include <ceres/problem.h>

#include <Eigen/Core>
#include <vector>

#include "calib/solver/camera_block.h"

namespace ws::calib {

inline constexpr double kGaugeWeight = 10.0;

// The prior's matrix of `camera`, whose field and radial model are set (the
// gauge patterns at its parameters): not M itself but its square root R
// (M = Q R, R upper triangular, at most as many rows as c), the same cost
// |R c|^2 = |M c|^2 in a third of the rows.
Eigen::MatrixXd NonRadialPrior(const CameraBlock& camera, double lambda);

// Adds e = camera.field_prior c when the camera has a field, c in the
// blocks `field`: its segments (field_blocks.h) in order, every one, then
// (ignored) the tilt's.
void AddNonRadialPrior(ceres::Problem& problem, const CameraBlock& camera,
                       const std::vector<double*>& field);

}  // namespace ws::calib
