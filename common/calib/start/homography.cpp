#include "calib/start/homography.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

namespace ws::calib {
namespace {

// The similarity taking the points to centroid 0 and mean distance sqrt(2).
Eigen::Matrix3d Normalizer(const std::vector<Eigen::Vector2d>& points) {
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& p : points) mean += p;
  mean /= double(points.size());
  double dist = 0;
  for (const auto& p : points) dist += (p - mean).norm();
  dist /= double(points.size());
  const double s = dist > 0 ? std::sqrt(2.0) / dist : 1.0;
  Eigen::Matrix3d T;
  T << s, 0, -s * mean.x(), 0, s, -s * mean.y(), 0, 0, 1;
  return T;
}

Eigen::Vector2d Apply(const Eigen::Matrix3d& H, const Eigen::Vector2d& p) {
  const Eigen::Vector3d q = H * p.homogeneous();
  return q.hnormalized();
}

bool Finite(const Eigen::Matrix3d& m) { return m.allFinite(); }

// Gauss-Newton with Levenberg damping on the pixel error, all 9 entries free
// (the scale is fixed by renormalising after each step).
Eigen::Matrix3d RefineHomography(Eigen::Matrix3d H, const std::vector<Eigen::Vector2d>& plane,
                                 const std::vector<Eigen::Vector2d>& image) {
  auto cost = [&](const Eigen::Matrix3d& h) {
    double sum = 0;
    for (size_t i = 0; i < plane.size(); ++i) {
      const Eigen::Vector3d q = h * plane[i].homogeneous();
      if (!(std::abs(q.z()) > 1e-12)) return std::numeric_limits<double>::infinity();
      sum += (q.hnormalized() - image[i]).squaredNorm();
    }
    return sum;
  };
  double current = cost(H);
  double lambda = 1e-3;
  for (int iteration = 0; iteration < 10 && std::isfinite(current); ++iteration) {
    Eigen::Matrix<double, 9, 9> JtJ = Eigen::Matrix<double, 9, 9>::Zero();
    Eigen::Matrix<double, 9, 1> Jte = Eigen::Matrix<double, 9, 1>::Zero();
    for (size_t i = 0; i < plane.size(); ++i) {
      const Eigen::Vector3d X = plane[i].homogeneous();
      const Eigen::Vector3d q = H * X;
      const double w = q.z();
      const Eigen::Vector2d e(q.x() / w - image[i].x(), q.y() / w - image[i].y());
      Eigen::Matrix<double, 2, 9> J = Eigen::Matrix<double, 2, 9>::Zero();
      // H row-major: entries 0..2 row 0, 3..5 row 1, 6..8 row 2.
      J.block<1, 3>(0, 0) = X.transpose() / w;
      J.block<1, 3>(1, 3) = X.transpose() / w;
      J.block<1, 3>(0, 6) = -q.x() / (w * w) * X.transpose();
      J.block<1, 3>(1, 6) = -q.y() / (w * w) * X.transpose();
      JtJ += J.transpose() * J;
      Jte += J.transpose() * e;
    }
    bool improved = false;
    for (int attempt = 0; attempt < 8; ++attempt) {
      Eigen::Matrix<double, 9, 9> A = JtJ;
      A.diagonal() *= 1.0 + lambda;
      const Eigen::Matrix<double, 9, 1> step = A.ldlt().solve(-Jte);
      Eigen::Matrix3d trial = H;
      for (int k = 0; k < 9; ++k) trial(k / 3, k % 3) += step(k);
      trial /= trial.norm();
      const double c = cost(trial);
      if (c < current) {
        const bool small = current - c < 1e-12 * (1 + current);
        H = trial;
        current = c;
        lambda = std::max(lambda * 0.1, 1e-9);
        improved = !small;
        break;
      }
      lambda *= 10;
    }
    if (!improved) break;
  }
  return H;
}

bool Plausible(double fx, double fy, double cx, double cy, int width, int height) {
  if (!std::isfinite(fx) || !std::isfinite(fy) || !std::isfinite(cx) || !std::isfinite(cy))
    return false;
  if (!(fx > 0) || !(fy > 0)) return false;
  if (fx / fy > 3 || fy / fx > 3) return false;
  return std::abs(cx - (width - 1) / 2.0) <= 0.3 * width &&
         std::abs(cy - (height - 1) / 2.0) <= 0.3 * height;
}

}  // namespace

std::optional<Eigen::Matrix3d> EstimateHomography(const std::vector<Eigen::Vector2d>& plane,
                                                  const std::vector<Eigen::Vector2d>& image) {
  const int n = static_cast<int>(plane.size());
  if (n < 4 || image.size() != plane.size()) return std::nullopt;
  const Eigen::Matrix3d Tp = Normalizer(plane), Ti = Normalizer(image);
  Eigen::MatrixXd A(2 * n, 9);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d X = Apply(Tp, plane[i]), u = Apply(Ti, image[i]);
    A.row(2 * i) << -X.x(), -X.y(), -1, 0, 0, 0, u.x() * X.x(), u.x() * X.y(), u.x();
    A.row(2 * i + 1) << 0, 0, 0, -X.x(), -X.y(), -1, u.y() * X.x(), u.y() * X.y(), u.y();
  }
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeFullV);
  const Eigen::VectorXd sv = svd.singularValues();
  // A rank below 8 means the points do not determine the homography.
  if (!(sv(7) > 1e-9 * sv(0))) return std::nullopt;
  const Eigen::VectorXd h = svd.matrixV().col(8);
  Eigen::Matrix3d Hn;
  Hn << h(0), h(1), h(2), h(3), h(4), h(5), h(6), h(7), h(8);
  Eigen::Matrix3d H = Ti.inverse() * Hn * Tp;
  if (!Finite(H) || !(H.norm() > 0)) return std::nullopt;
  H /= H.norm();
  H = RefineHomography(H, plane, image);
  if (std::abs(H(2, 2)) > 1e-12) H /= H(2, 2);
  if (!Finite(H)) return std::nullopt;
  return H;
}

namespace {

// Zhang's constraints h1^T B h2 = 0 and h1^T B h1 = h2^T B h2 on
// B = K^-T K^-1 with the principal point at the origin (B = diag(1/fx^2,
// 1/fy^2, 1)): rows of A (in 1/fx^2, 1/fy^2) and the right-hand side.
void CentredSystem(const std::vector<Eigen::Matrix3d>& Hs, Eigen::MatrixXd* A,
                   Eigen::VectorXd* rhs) {
  const int n = static_cast<int>(Hs.size());
  A->resize(2 * n, 2);
  rhs->resize(2 * n);
  for (int k = 0; k < n; ++k) {
    const Eigen::Matrix3d& H = Hs[k];
    A->row(2 * k) << H(0, 0) * H(0, 1), H(1, 0) * H(1, 1);
    (*rhs)(2 * k) = -H(2, 0) * H(2, 1);
    A->row(2 * k + 1) << H(0, 0) * H(0, 0) - H(0, 1) * H(0, 1),
        H(1, 0) * H(1, 0) - H(1, 1) * H(1, 1);
    (*rhs)(2 * k + 1) = -(H(2, 0) * H(2, 0) - H(2, 1) * H(2, 1));
  }
}

// fx, fy with the principal point at the origin; nullopt when not positive.
std::optional<Eigen::Vector4d> Centred(const std::vector<Eigen::Matrix3d>& Hs) {
  if (Hs.size() < 2) return std::nullopt;
  Eigen::MatrixXd A;
  Eigen::VectorXd rhs;
  CentredSystem(Hs, &A, &rhs);
  const Eigen::Vector2d x = A.colPivHouseholderQr().solve(rhs);
  if (!(x(0) > 0 && x(1) > 0)) return std::nullopt;
  return Eigen::Vector4d(1 / std::sqrt(x(0)), 1 / std::sqrt(x(1)), 0, 0);
}

// fx = fy with the principal point at the origin.
std::optional<Eigen::Vector4d> Square(const std::vector<Eigen::Matrix3d>& Hs) {
  if (Hs.empty()) return std::nullopt;
  Eigen::MatrixXd A;
  Eigen::VectorXd rhs;
  CentredSystem(Hs, &A, &rhs);
  const Eigen::VectorXd a = A.col(0) + A.col(1);
  const double x = a.dot(rhs) / a.squaredNorm();
  if (!(x > 0)) return std::nullopt;
  return Eigen::Vector4d(1 / std::sqrt(x), 1 / std::sqrt(x), 0, 0);
}

// The full zero-skew form, b = (B11, B22, B13, B23, B33) (needs 3 views);
// nullopt unless one singular value is clearly the smallest.
std::optional<Eigen::Vector4d> Full(const std::vector<Eigen::Matrix3d>& Hs) {
  const int n = static_cast<int>(Hs.size());
  if (n < 3) return std::nullopt;
  auto v = [](const Eigen::Matrix3d& H, int i, int j) {
    Eigen::Matrix<double, 1, 5> row;
    row << H(0, i) * H(0, j), H(1, i) * H(1, j), H(2, i) * H(0, j) + H(0, i) * H(2, j),
        H(2, i) * H(1, j) + H(1, i) * H(2, j), H(2, i) * H(2, j);
    return row;
  };
  Eigen::MatrixXd V(2 * n, 5);
  for (int k = 0; k < n; ++k) {
    V.row(2 * k) = v(Hs[k], 0, 1);
    V.row(2 * k + 1) = v(Hs[k], 0, 0) - v(Hs[k], 1, 1);
  }
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(V, Eigen::ComputeFullV);
  if (!(svd.singularValues()(4) < 0.5 * svd.singularValues()(3))) return std::nullopt;
  Eigen::Matrix<double, 5, 1> b = svd.matrixV().col(4);
  if (b(0) < 0) b = -b;
  const double B11 = b(0), B22 = b(1), B13 = b(2), B23 = b(3), B33 = b(4);
  const double vc = -B23 / B22;
  const double lambda = B33 - (B13 * B13 - vc * B11 * B23) / B11;
  const double fx = std::sqrt(lambda / B11), fy = std::sqrt(lambda / B22);
  return Eigen::Vector4d(fx, fy, -B13 * fx * fx / lambda, vc);
}

}  // namespace

PinholeInit ZhangIntrinsics(const std::vector<Eigen::Matrix3d>& homographies, int image_width,
                            int image_height) {
  // Work in normalised pixels (origin at the image centre) so that every
  // entry of B is of order one.
  const double scale = (image_width + image_height) / 2.0;
  const double u0 = (image_width - 1) / 2.0, v0 = (image_height - 1) / 2.0;
  Eigen::Matrix3d N;
  N << 1 / scale, 0, -u0 / scale, 0, 1 / scale, -v0 / scale, 0, 0, 1;
  std::vector<Eigen::Matrix3d> Hs;
  for (const auto& H : homographies) {
    Eigen::Matrix3d h = N * H;
    if (!h.allFinite() || !(h.norm() > 0)) continue;
    Hs.push_back(h / h.norm());
  }
  using Method = std::optional<Eigen::Vector4d> (*)(const std::vector<Eigen::Matrix3d>&);
  const std::pair<Method, const char*> methods[] = {
      {Centred, "zhang-centred"}, {Square, "zhang-square"}, {Full, "zhang"}};
  for (const auto& [method, name] : methods) {
    const auto k = method(Hs);
    if (!k) continue;
    const PinholeInit init{(*k)(0) * scale, (*k)(1) * scale, (*k)(2) * scale + u0,
                           (*k)(3) * scale + v0, name};
    if (Plausible(init.fx, init.fy, init.cx, init.cy, image_width, image_height)) return init;
  }
  throw CalibrationError(
      "no focal length fits the board views (Zhang's closed form failed even with the principal "
      "point at the image centre): the views are probably all (nearly) parallel to each other or "
      "to the image; tilt the board by 20-40 degrees in different directions");
}

Pose PoseFromHomography(const Eigen::Matrix3d& H, const Eigen::Matrix3d& K) {
  const Eigen::Matrix3d M = K.inverse() * H;
  double lambda = 2.0 / (M.col(0).norm() + M.col(1).norm());
  if (lambda * M(2, 2) < 0) lambda = -lambda;
  const Eigen::Vector3d r1 = lambda * M.col(0), r2 = lambda * M.col(1);
  Eigen::Matrix3d R;
  R << r1, r2, r1.cross(r2);
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(R, Eigen::ComputeFullU | Eigen::ComputeFullV);
  R = svd.matrixU() * svd.matrixV().transpose();
  if (R.determinant() < 0) {
    Eigen::Matrix3d U = svd.matrixU();
    U.col(2) = -U.col(2);
    R = U * svd.matrixV().transpose();
  }
  return Pose::FromRt(R, lambda * M.col(2));
}

double MaxNormalAngleDeg(const std::vector<Pose>& board_poses) {
  std::vector<Eigen::Vector3d> normals;
  for (const auto& pose : board_poses) normals.push_back(pose.R().col(2));
  double max_angle = 0;
  for (size_t i = 0; i < normals.size(); ++i)
    for (size_t j = i + 1; j < normals.size(); ++j) {
      const double c = std::clamp(normals[i].dot(normals[j]), -1.0, 1.0);
      max_angle = std::max(max_angle, std::acos(c) * 180.0 / M_PI);
    }
  return max_angle;
}

}  // namespace ws::calib
