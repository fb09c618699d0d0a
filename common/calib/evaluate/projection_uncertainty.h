// Projection uncertainty (issue #14): how far, in pixels, the calibrated
// camera's projection of a fixed point may be off, from the solver's own
// covariance.
//
// Definition. Let p be the camera's parameters (fx fy cx cy p1 p2 and the
// model's estimated coefficients) and C_p their covariance: sigma^2 (J^T J)^-1
// of the final solve with every board pose marginalised (the Schur
// complement, covariance.h; sigma^2 the fit's own noise level). For a pixel
// q of the image let v be its ray under the solved camera, held fixed in the
// camera frame, and q(p) = project(v; p). To first order
//
//   Sigma_q = (dq/dp) C_p (dq/dp)^T        (a 2 x 2 covariance, pixels^2)
//
// and the 1-sigma uncertainty at q is the worst direction's standard
// deviation, sqrt(largest eigenvalue of Sigma_q) (mrcal's
// "worstdirection-stdev"). The derivatives are exact (Ceres Jets through
// the model's templated Project). A point far away or near gives the same
// value: only v's direction enters a single camera's projection.
//
// Against mrcal's projection_uncertainty: mrcal also propagates the board
// poses' uncertainty into where the camera frame sits relative to the
// boards (its "mean frames" reference), which removes the part of the
// variation a small rotation of the camera explains; this definition keeps
// it (the camera frame is the reference), so it is the larger of the two
// where cx, cy are uncertain. It is what a re-calibration from new noise
// moves a camera-frame ray by: the check in tests/calib compares it with 20
// re-noised solves.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "calib/evaluate/image_grid.h"
#include "calib/solver/camera_block.h"

namespace ws::calib {

struct ProjectionUncertainty {
  ImageGrid grid;
  std::vector<double> sigma_px;    // per grid point; NaN where no ray
  std::vector<char> observed;      // 1 where an inlier corner lies in the grid cell
  double median_px = -1;           // over the observed cells; negative: none
  double worst_px = -1;

  bool empty() const { return sigma_px.empty(); }
};

// The 2 x 2 covariance of projecting the camera-frame direction `ray` given
// the parameters' covariance C_p (over intrinsics then coefficients, the
// CameraBlock's layout); nullopt where the ray does not project.
std::optional<Eigen::Matrix2d> ProjectionCovariance(const CameraBlock& camera,
                                                    const Eigen::MatrixXd& covariance,
                                                    const Eigen::Vector3d& ray);

// The worst direction's standard deviation of a 2 x 2 covariance.
double WorstDirectionSigma(const Eigen::Matrix2d& covariance);

// The uncertainty over a cols x rows grid of the image; `corners` (the
// inlier corners, pixels) mark the observed cells. Empty when `covariance`
// does not match the camera's parameters.
ProjectionUncertainty MapProjectionUncertainty(const CameraBlock& camera,
                                               const Eigen::MatrixXd& covariance, int width,
                                               int height,
                                               const std::vector<Eigen::Vector2d>& corners,
                                               int cols = 32, int rows = 24);

}  // namespace ws::calib
