#include "calib/evaluate/projection_uncertainty.h"

#include <ceres/jet.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "calib/solver/quality.h"
#include "models/projection.h"

namespace ws::calib {
namespace {

using Jet = ceres::Jet<double, 1>;

// dq/dp at the ray: column k from a Jet seeded on parameter k.
std::optional<Eigen::MatrixXd> ProjectionJacobian(const CameraBlock& camera,
                                                  const Eigen::Vector3d& ray) {
  const int n = kNumIntrinsics + int(camera.coeffs.size());
  std::vector<Jet> params(n);
  for (int k = 0; k < kNumIntrinsics; ++k) params[k] = Jet(camera.intrinsics[k]);
  for (size_t k = 0; k < camera.coeffs.size(); ++k)
    params[kNumIntrinsics + k] = Jet(camera.coeffs[k]);
  const Jet point[3] = {Jet(ray.x()), Jet(ray.y()), Jet(ray.z())};
  Eigen::MatrixXd J(2, n);
  for (int k = 0; k < n; ++k) {
    params[k].v[0] = 1;
    Jet pixel[2];
    const bool in_front = std::visit(
        [&](const auto& m) {
          return Project(m, camera.field, params.data(), params.data() + kNumIntrinsics, point,
                         pixel);
        },
        camera.model);
    params[k].v[0] = 0;
    if (!in_front || !std::isfinite(pixel[0].v[0]) || !std::isfinite(pixel[1].v[0]))
      return std::nullopt;
    J(0, k) = pixel[0].v[0];
    J(1, k) = pixel[1].v[0];
  }
  return J;
}

}  // namespace

std::optional<Eigen::Matrix2d> ProjectionCovariance(const CameraBlock& camera,
                                                    const Eigen::MatrixXd& covariance,
                                                    const Eigen::Vector3d& ray) {
  const auto J = ProjectionJacobian(camera, ray);
  if (!J || covariance.rows() != J->cols() || covariance.cols() != J->cols()) return std::nullopt;
  return Eigen::Matrix2d(*J * covariance * J->transpose());
}

double WorstDirectionSigma(const Eigen::Matrix2d& covariance) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(covariance);
  return std::sqrt(std::max(0.0, eig.eigenvalues()(1)));
}

ProjectionUncertainty MapProjectionUncertainty(const CameraBlock& camera,
                                               const Eigen::MatrixXd& covariance, int width,
                                               int height,
                                               const std::vector<Eigen::Vector2d>& corners,
                                               int cols, int rows) {
  ProjectionUncertainty map;
  const int n = kNumIntrinsics + int(camera.coeffs.size());
  if (covariance.rows() != n || covariance.cols() != n || width <= 0 || height <= 0) return map;
  map.grid = ImageGrid::Over(width, height, cols, rows);
  map.sigma_px.assign(map.grid.size(), NAN);
  map.observed.assign(map.grid.size(), 0);
  for (const Eigen::Vector2d& q : corners)
    if (const auto cell = map.grid.Cell(q)) map.observed[*cell] = 1;
  std::vector<double> observed;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < cols; ++i) {
      const auto ray = PixelRay(camera, map.grid.Pixel(i, j));
      if (!ray) continue;
      const auto sigma = ProjectionCovariance(camera, covariance, *ray);
      if (!sigma) continue;
      const size_t k = size_t(j) * cols + i;
      map.sigma_px[k] = WorstDirectionSigma(*sigma);
      if (map.observed[k]) observed.push_back(map.sigma_px[k]);
    }
  map.median_px = Median(observed);
  if (!observed.empty()) map.worst_px = *std::max_element(observed.begin(), observed.end());
  return map;
}

}  // namespace ws::calib
