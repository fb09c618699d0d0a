// The difference between two calibrations of one camera, in pixels across
// its image (issue #14, stereo-compare; mrcal-show-projection-diff's
// definition): for each pixel q of a grid over camera A's image, the ray
// v = unproject_A(q), and
//
//   diff(q) = | project_B(R v) - q |
//
// with R the small rotation between the two camera frames that fits best.
// Two calibrations fix a camera's frame only up to such a rotation (a
// shift of cx is nearly a turn of the camera, and the board poses follow),
// so without it two equally good calibrations can differ by pixels that
// mean nothing. R minimises the sum of diff(q)^2 over the grid points
// within `fit_radius` pixels of the image centre (mrcal's default: a sixth
// of the smaller image side; the centre is where both are best observed),
// by Gauss-Newton on its angle-axis; fit_radius <= 0: R = I (no fit).
// Grid points that either camera cannot carry (no ray, no pixel, a pixel
// outside B's image, or a ray outside either model's calibrated field,
// CameraProjection::InField) are NaN and left out of every statistic.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "calib/evaluate/image_grid.h"
#include "interop/camera_projection.h"

namespace ws::calib {

struct ProjectionDiff {
  ImageGrid grid;
  std::vector<double> diff_px;    // per grid point; NaN where not compared
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // applied to A's rays
  double rotation_deg = 0;
  int fit_points = 0;  // grid points the rotation was fitted to
  int points = 0;      // grid points compared
  double rms_px = 0, median_px = 0, max_px = 0;
};

// The default fit radius: a sixth of the smaller image side.
double DefaultFitRadius(const CameraProjection& camera);

// Compares camera B against camera A (A's image is the grid's); either may
// be another tool's model (interop/any_rig.h). Throws
// std::invalid_argument when the two cameras' image sizes differ, and
// std::runtime_error when no grid point projects through both (a
// difference over nothing).
ProjectionDiff CompareProjection(const CameraProjection& a, const CameraProjection& b, double fit_radius,
                                 int cols = 64, int rows = 48);

}  // namespace ws::calib
