// Parameter standard deviations from the solved problem.
//
// Cov = sigma^2 (J^T J)^-1 restricted to the camera parameters, where the
// board poses (each touching only its own residual blocks) are eliminated by
// the Schur complement: S = H_ff - sum_j H_fj H_jj^-1 H_jf over the 6x6 pose
// blocks H_jj, Cov_ff = sigma^2 S^-1. sigma^2 = (sum of squared data
// residuals) / (number of data residuals - number of free parameters): the
// noise level the fit itself shows, as OpenCV's calibrateCamera does for its
// stdDeviations. The smoothness prior's residuals are part of J (they are
// information) but not of sigma^2. This is exact and much cheaper than
// Ceres's general covariance for hundreds of pose parameters.
#pragma once

#include <ceres/problem.h>

#include <Eigen/Core>
#include <optional>
#include <vector>

namespace ws::calib {

// The inverse of a board pose's 6 x 6 block of J^T J (by its eigen
// decomposition); none unless it is positive definite, its smallest
// eigenvalue above 1e-12 of the largest (or of 1): the pose's corners fix it.
std::optional<Eigen::Matrix<double, 6, 6>> PoseBlockInverse(const Eigen::Matrix<double, 6, 6>& H);

// Covariance of the concatenated `blocks` (their sizes in the problem),
// eliminating `poses` (blocks of 6). Every non-constant parameter block of
// the problem must be in one of the two lists. nullopt if S is not positive
// definite (then the parameters are not determined by the data).
std::optional<Eigen::MatrixXd> CameraCovariance(ceres::Problem& problem,
                                                const std::vector<double*>& blocks,
                                                const std::vector<double*>& poses, double sigma2);

}  // namespace ws::calib
