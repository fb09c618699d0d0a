#include "calib/solver/covariance.h"

#include <ceres/crs_matrix.h>

#include <Eigen/Dense>
#include <cmath>
#include <vector>

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
  // The blocks of J^T J the elimination needs, summed row by row over each
  // row's entries (a corner's row reads its pose, its camera and a few of
  // the field's control points): by the free parameters, by them and the
  // poses, and each pose's own 6 x 6.
  Eigen::MatrixXd Hff = Eigen::MatrixXd::Zero(nf, nf), Hfe = Eigen::MatrixXd::Zero(nf, ne);
  std::vector<Eigen::Matrix<double, 6, 6>> Hee(poses.size(), Eigen::Matrix<double, 6, 6>::Zero());
  for (int r = 0; r < crs.num_rows; ++r)
    for (int a = crs.rows[r]; a < crs.rows[r + 1]; ++a)
      for (int b = crs.rows[r]; b < crs.rows[r + 1]; ++b) {
        const int ca = crs.cols[a], cb = crs.cols[b];
        const double v = crs.values[a] * crs.values[b];
        if (ca >= ne && cb >= ne) Hff(ca - ne, cb - ne) += v;
        else if (ca >= ne) Hfe(ca - ne, cb) += v;
        else if (cb < ne && ca / 6 == cb / 6) Hee[size_t(ca / 6)](ca % 6, cb % 6) += v;
      }
  for (size_t j = 0; j < poses.size(); ++j) {
    const auto inv = PoseBlockInverse(Hee[j]);
    if (!inv) return std::nullopt;
    const auto Hfj = Hfe.middleCols(6 * Eigen::Index(j), 6);
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
