#include "rectify/pair_triangulation.h"

namespace ws {

std::optional<Eigen::Vector3d> TriangulatePixels(const Camera& left, const Camera& right,
                                                 const Eigen::Matrix3d& R, const Eigen::Vector3d& T,
                                                 const Eigen::Vector2d& left_pixel,
                                                 const Eigen::Vector2d& right_pixel) {
  const auto rl = left.Unproject(left_pixel);
  const auto rr = right.Unproject(right_pixel);
  if (!rl || !rr) return std::nullopt;
  const Eigen::Vector3d c = -R.transpose() * T;
  const Eigen::Vector3d d = R.transpose() * *rr;
  // Normal equations of [r_l -d] [s t]^T = c with |r_l| = |d| = 1.
  const double b = rl->dot(d), f1 = rl->dot(c), f2 = d.dot(c);
  const double det = 1.0 - b * b;
  if (!(det > 1e-12)) return std::nullopt;
  const double s = (f1 - b * f2) / det, t = (b * f1 - f2) / det;
  if (!(s > 0) || !(t > 0)) return std::nullopt;
  return 0.5 * (s * *rl + c + t * d);
}

}  // namespace ws
