#include "calib/start/ray_pose.h"

#include <Eigen/Dense>
#include <cmath>

namespace ws::calib {

std::optional<Pose> PoseFromRays(const std::vector<Eigen::Vector3d>& object,
                                 const std::vector<Eigen::Vector3d>& rays) {
  const int n = static_cast<int>(object.size());
  if (n < 4 || static_cast<int>(rays.size()) != n) return std::nullopt;
  // Hartley's normalisation of the board points: centred, mean distance sqrt 2.
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& X : object) {
    if (std::abs(X.z()) > 1e-9) return std::nullopt;
    mean += X.head<2>();
  }
  mean /= n;
  double spread = 0;
  for (const auto& X : object) spread += (X.head<2>() - mean).norm();
  if (!(spread > 0)) return std::nullopt;
  const double s = std::sqrt(2.0) * n / spread;
  Eigen::Matrix3d N;
  N << s, 0, -s * mean.x(), 0, s, -s * mean.y(), 0, 0, 1;

  // d x (H' m') = 0, three rows per point in h = H' row-major.
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(3 * n, 9);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d m = N * Eigen::Vector3d(object[i].x(), object[i].y(), 1.0);
    const Eigen::Vector3d d = rays[i].normalized();
    // (H' m)_k = h.segment<3>(3k) . m; row r of d x v: eps_rjk d_j v_k.
    for (int r = 0; r < 3; ++r) {
      const int j = (r + 1) % 3, k = (r + 2) % 3;
      A.block<1, 3>(3 * i + r, 3 * k) += d(j) * m.transpose();
      A.block<1, 3>(3 * i + r, 3 * j) -= d(k) * m.transpose();
    }
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeFullV);
  const Eigen::VectorXd h = svd.matrixV().col(8);
  Eigen::Matrix3d H;
  H << h(0), h(1), h(2), h(3), h(4), h(5), h(6), h(7), h(8);
  H = H * N;
  // Sign: H m_i along d_i, not against it.
  double along = 0;
  for (int i = 0; i < n; ++i)
    along += rays[i].dot(H * Eigen::Vector3d(object[i].x(), object[i].y(), 1.0));
  if (!(std::abs(along) > 0)) return std::nullopt;
  const double scale = (along > 0 ? 2.0 : -2.0) / (H.col(0).norm() + H.col(1).norm());
  Eigen::Matrix3d R;
  R.col(0) = scale * H.col(0);
  R.col(1) = scale * H.col(1);
  R.col(2) = R.col(0).cross(R.col(1));
  const Eigen::JacobiSVD<Eigen::Matrix3d> nearest(R, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d rotation = nearest.matrixU() * nearest.matrixV().transpose();
  if (rotation.determinant() < 0) return std::nullopt;
  const Pose pose = Pose::FromRt(rotation, scale * H.col(2));
  if (!pose.AllFinite()) return std::nullopt;
  return pose;
}

}  // namespace ws::calib
