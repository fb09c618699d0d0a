#include "calib/solver/covariance.h"

#include <ceres/crs_matrix.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace ws::calib {

std::optional<Eigen::Matrix<double, 6, 6>> PoseBlockInverse(const Eigen::Matrix<double, 6, 6>& H) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eig(H);
  const auto& values = eig.eigenvalues();
  if (!(values(0) > 1e-12 * std::max(1.0, values(5)))) return std::nullopt;
  return Eigen::Matrix<double, 6, 6>(eig.eigenvectors() * values.cwiseInverse().asDiagonal() *
                                     eig.eigenvectors().transpose());
}

namespace {

// The inverse of the symmetric `scaled` (unit diagonal), none unless its
// smallest eigenvalue is above 1e-14 of its largest (the parameters are
// determined by the data). Where the Cholesky factor's reciprocal condition
// estimate (1-norm; within a factor of the size of the true one) is above
// 1e-8, the matrix is far from that limit and the Cholesky solve gives the
// inverse, in a tenth of the time of the eigenvalues (a camera with a field
// has hundreds of parameters); else the eigenvalues decide.
std::optional<Eigen::MatrixXd> Inverse(const Eigen::MatrixXd& scaled) {
  const Eigen::Index n = scaled.rows();
  const Eigen::LLT<Eigen::MatrixXd> llt(scaled);
  if (llt.info() == Eigen::Success && llt.rcond() > 1e-8) return llt.solve(Eigen::MatrixXd::Identity(n, n));
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(scaled);
  const Eigen::VectorXd values = eig.eigenvalues();
  if (!(values(0) > 1e-14 * values(n - 1))) return std::nullopt;
  return eig.eigenvectors() * values.cwiseInverse().asDiagonal() * eig.eigenvectors().transpose();
}

}  // namespace

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
  // The blocks of J^T J the elimination needs: by the free parameters, by
  // them and the poses, and each pose's own 6 x 6. Each run of rows over the
  // same columns (a residual block's: a pose, the camera, the field segments
  // its corners read) is one dense product, scattered.
  Eigen::MatrixXd Hff = Eigen::MatrixXd::Zero(nf, nf), Hfe = Eigen::MatrixXd::Zero(nf, ne);
  std::vector<Eigen::Matrix<double, 6, 6>> Hee(poses.size(), Eigen::Matrix<double, 6, 6>::Zero());
  using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  for (int first = 0, last = 0; first < crs.num_rows; first = last) {
    const int begin = crs.rows[first], k = crs.rows[first + 1] - begin;
    const auto columns = crs.cols.begin() + begin;
    for (last = first + 1; last < crs.num_rows && crs.rows[last + 1] - crs.rows[last] == k &&
                           std::equal(columns, columns + k, crs.cols.begin() + crs.rows[last]);
         ++last) {
    }
    const Eigen::Map<const RowMajor> J(crs.values.data() + begin, last - first, k);  // rows stored in turn
    const Eigen::MatrixXd JtJ = J.transpose() * J;
    for (int a = 0; a < k; ++a)
      for (int b = 0; b < k; ++b) {
        const int ca = columns[a], cb = columns[b];
        if (ca >= ne && cb >= ne) Hff(ca - ne, cb - ne) += JtJ(a, b);
        else if (ca >= ne) Hfe(ca - ne, cb) += JtJ(a, b);
        else if (cb < ne && ca / 6 == cb / 6) Hee[size_t(ca / 6)](ca % 6, cb % 6) += JtJ(a, b);
      }
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
  const std::optional<Eigen::MatrixXd> inv_scaled = Inverse(scaled);
  if (!inv_scaled) return std::nullopt;
  Eigen::MatrixXd cov = sigma2 * (d.asDiagonal() * *inv_scaled * d.asDiagonal());
  if (!cov.allFinite()) return std::nullopt;
  return cov;
}

}  // namespace ws::calib
