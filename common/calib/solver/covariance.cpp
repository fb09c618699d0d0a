#include "calib/solver/covariance.h"

#include <ceres/crs_matrix.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <cmath>

namespace ws::calib {

std::optional<Eigen::Matrix<double, 6, 6>> PoseBlockInverse(const Eigen::Matrix<double, 6, 6>& H) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eig(H);
  const auto& values = eig.eigenvalues();
  if (!(values(0) > 1e-12 * std::max(1.0, values(5)))) return std::nullopt;
  return Eigen::Matrix<double, 6, 6>(eig.eigenvectors() * values.cwiseInverse().asDiagonal() *
                                     eig.eigenvectors().transpose());
}

std::optional<Eigen::MatrixXd> CameraCovariance(ceres::Problem& problem,
                                                const std::vector<double*>& blocks,
                                                const std::vector<double*>& poses, double sigma2) {
  ceres::Problem::EvaluateOptions options;
  options.parameter_blocks = poses;
  options.parameter_blocks.insert(options.parameter_blocks.end(), blocks.begin(), blocks.end());
  options.apply_loss_function = true;
  options.num_threads = 1;
  ceres::CRSMatrix crs;
  if (!problem.Evaluate(options, nullptr, nullptr, nullptr, &crs)) return std::nullopt;
  const int ne = 6 * static_cast<int>(poses.size());
  const int cols = crs.num_cols;
  const int nf = cols - ne;
  if (nf <= 0) return std::nullopt;
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(crs.values.size());
  for (int r = 0; r < crs.num_rows; ++r)
    for (int k = crs.rows[r]; k < crs.rows[r + 1]; ++k)
      triplets.emplace_back(r, crs.cols[k], crs.values[k]);
  Eigen::SparseMatrix<double> J(crs.num_rows, cols);
  J.setFromTriplets(triplets.begin(), triplets.end());
  const Eigen::SparseMatrix<double> H = J.transpose() * J;
  Eigen::MatrixXd Hff = Eigen::MatrixXd(H.bottomRightCorner(nf, nf));
  const Eigen::MatrixXd Hfe = Eigen::MatrixXd(H.block(ne, 0, nf, ne));
  for (int j = 0; j < ne; j += 6) {
    const auto inv = PoseBlockInverse(Eigen::MatrixXd(H.block(j, j, 6, 6)));
    if (!inv) return std::nullopt;
    const auto Hfj = Hfe.middleCols(j, 6);
    Hff.noalias() -= Hfj * *inv * Hfj.transpose();
  }
  Hff = 0.5 * (Hff + Hff.transpose());
  // Scale to unit diagonal before the eigen decomposition: the parameters'
  // units differ by many orders of magnitude (pixels, distortion, metres).
  const Eigen::VectorXd d = Hff.diagonal().cwiseMax(1e-300).cwiseSqrt().cwiseInverse();
  const Eigen::MatrixXd scaled = d.asDiagonal() * Hff * d.asDiagonal();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(scaled);
  const Eigen::VectorXd values = eig.eigenvalues();
  if (!(values(0) > 1e-14 * values(nf - 1))) return std::nullopt;
  const Eigen::MatrixXd inv_scaled =
      eig.eigenvectors() * values.cwiseInverse().asDiagonal() * eig.eigenvectors().transpose();
  Eigen::MatrixXd cov = sigma2 * (d.asDiagonal() * inv_scaled * d.asDiagonal());
  if (!cov.allFinite()) return std::nullopt;
  return cov;
}

}  // namespace ws::calib
