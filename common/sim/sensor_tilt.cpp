#include "sim/sensor_tilt.h"

#include <Eigen/Dense>
#include <cmath>
#include <stdexcept>
#include <string>

namespace ws {
namespace {

// M(tau) of sensor_tilt.h.
Eigen::Matrix3d TiltMatrix(const std::array<double, 2>& tau) {
  const Eigen::Matrix3d R = (Eigen::AngleAxisd(tau[1], Eigen::Vector3d::UnitY()) *
                             Eigen::AngleAxisd(tau[0], Eigen::Vector3d::UnitX()))
                                .toRotationMatrix();
  Eigen::Matrix3d M;
  M << R(2, 2), 0, -R(0, 2), 0, R(2, 2), -R(1, 2), 0, 0, 1;
  return M * R;
}

}  // namespace

CameraModel WithSensorTilt(const CameraModel& model, const std::array<double, 2>& tau) {
  if (tau[0] == 0 && tau[1] == 0) return model;
  const Eigen::Matrix3d M = TiltMatrix(tau);
  const int w = model.image_width, h = model.image_height;
  const int cols = kTiltGrid, rows = std::max(4, int(std::lround(kTiltGrid * double(h) / w)));
  const double mu = 0.01 * w, mv = 0.01 * h;  // as calibration sets a field up (camera_block.h)
  const NonRadialField field(cols, rows,
                             {(-0.5 - mu - model.cx) / model.fx, (w - 0.5 + mu - model.cx) / model.fx,
                              (-0.5 - mv - model.cy) / model.fy, (h - 0.5 + mv - model.cy) / model.fy});
  // F(p) = tilt(p) - p at samples 4 per control point each way, least squares.
  const auto& d = field.domain();
  const int ns = 4 * cols, nt = 4 * rows, half = cols * rows;
  auto displacement = [&](double s, double t) {
    const Eigen::Vector3d q = M * Eigen::Vector3d(s, t, 1);
    return Eigen::Vector2d(q.x() / q.z() - s, q.y() / q.z() - t);
  };
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(ns * nt, half);
  Eigen::MatrixXd b(ns * nt, 2);
  for (int j = 0, k = 0; j < nt; ++j)
    for (int i = 0; i < ns; ++i, ++k) {
      const double s = d[0] + (d[1] - d[0]) * i / (ns - 1), t = d[2] + (d[3] - d[2]) * j / (nt - 1);
      const NonRadialField::Local local = field.LocalBasis(s, t);
      for (int l = 0; l < NonRadialField::kLocal; ++l) A(k, local.index[l]) += local.weight[l];
      b.row(k) = displacement(s, t).transpose();
    }
  const Eigen::MatrixXd c = A.colPivHouseholderQr().solve(b);
  CameraModel out = model;
  out.nonradial = {cols, rows, d, std::vector<double>(2 * half)};
  for (int k = 0; k < half; ++k) {
    out.nonradial.coeffs[k] = c(k, 0);
    out.nonradial.coeffs[half + k] = c(k, 1);
  }
  // The fit against the warp, between the samples too.
  for (int j = 0; j <= 2 * nt; ++j)
    for (int i = 0; i <= 2 * ns; ++i) {
      const double s = d[0] + (d[1] - d[0]) * i / (2 * ns), t = d[2] + (d[3] - d[2]) * j / (2 * nt);
      double f[2];
      field.Evaluate(out.nonradial.coeffs.data(), s, t, f);
      const Eigen::Vector2d e = Eigen::Vector2d(f[0], f[1]) - displacement(s, t);
      if (std::hypot(model.fx * e.x(), model.fy * e.y()) >= 1e-3)
        throw std::invalid_argument("a sensor tilt of (" + std::to_string(tau[0]) + ", " +
                                    std::to_string(tau[1]) +
                                    ") rad is too strong for the simulator's field to draw");
    }
  return out;
}

}  // namespace ws
