// Zhang's initialisation (Z. Zhang, "A Flexible New Technique for Camera
// Calibration", PAMI 2000): a homography per view of the plane board, the
// pinhole intrinsics in closed form from all of them, then each view's pose.
//
// Everything here is pinhole (no distortion): it only has to start the
// non-linear solver in the right basin. Homographies of a strongly distorted
// board are poor, and the full closed form then gives a B = K^-T K^-1 that is
// not positive definite (the "NaN focal length" of other tools) or a
// principal point far off; so, like OpenCV's own initialisation, the
// principal point starts at the image centre, and every result is checked.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "calib/solver/calib_data.h"
#include "calib/solver/pose.h"

namespace ws::calib {

// The homography H (H(2,2) = 1 when possible) mapping the board plane (X, Y)
// to pixels, by the normalised DLT (Hartley: both point sets centred and
// scaled to mean distance sqrt 2) followed by Gauss-Newton on the pixel
// error. nullopt for fewer than 4 points or a degenerate configuration.
std::optional<Eigen::Matrix3d> EstimateHomography(const std::vector<Eigen::Vector2d>& plane,
                                                  const std::vector<Eigen::Vector2d>& image);

// Pinhole intrinsics from the homographies (zero skew).
struct PinholeInit {
  double fx = 0, fy = 0, cx = 0, cy = 0;
  // How they were obtained: "zhang-centred" (principal point at the image
  // centre, fx and fy solved), "zhang-square" (principal point at the
  // centre, fx = fy), "zhang" (all four from the closed form).
  std::string method;
};

// Tries the principal point at the image centre ((w - 1) / 2, (h - 1) / 2)
// with fx and fy, then with fx = fy, then the full zero-skew closed form
// (needs 3 views). A result is accepted when the focal lengths are finite and
// positive, their ratio is within [1/3, 3] and the principal point is inside
// the middle 60 % of the image. Throws CalibrationError when none is.
PinholeInit ZhangIntrinsics(const std::vector<Eigen::Matrix3d>& homographies, int image_width,
                            int image_height);

// The board-to-camera pose of a view from its homography and K: r1, r2 from
// K^-1 h1, K^-1 h2 (scale from their mean norm, sign so that the board is in
// front, t_z > 0), r3 = r1 x r2, the nearest rotation by SVD.
Pose PoseFromHomography(const Eigen::Matrix3d& H, const Eigen::Matrix3d& K);

// The largest angle (degrees) between the board normals of any two poses;
// Zhang's method needs the board planes not to be all parallel.
double MaxNormalAngleDeg(const std::vector<Pose>& board_poses);

}  // namespace ws::calib
