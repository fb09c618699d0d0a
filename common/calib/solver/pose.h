// A rigid transform as one Ceres parameter block of 6: angle-axis rotation
// (rx, ry, rz; the axis times the angle in radians) and translation (tx, ty,
// tz), X_to = R X_from + t.
#pragma once

#include <ceres/rotation.h>

#include <Eigen/Core>
#include <array>
#include <cmath>

namespace ws::calib {

struct Pose {
  std::array<double, 6> data{};  // rx, ry, rz, tx, ty, tz

  double* rotation() { return data.data(); }
  const double* rotation() const { return data.data(); }
  double* translation() { return data.data() + 3; }
  const double* translation() const { return data.data() + 3; }

  Eigen::Matrix3d R() const {
    Eigen::Matrix3d m;
    ceres::AngleAxisToRotationMatrix(rotation(), ceres::ColumnMajorAdapter3x3(m.data()));
    return m;
  }
  Eigen::Vector3d t() const { return {data[3], data[4], data[5]}; }
  Eigen::Vector3d operator*(const Eigen::Vector3d& x) const { return R() * x + t(); }

  static Pose FromRt(const Eigen::Matrix3d& R, const Eigen::Vector3d& t) {
    Pose pose;
    ceres::RotationMatrixToAngleAxis(ceres::ColumnMajorAdapter3x3(R.data()), pose.rotation());
    pose.data[3] = t.x();
    pose.data[4] = t.y();
    pose.data[5] = t.z();
    return pose;
  }
  bool AllFinite() const {
    for (double v : data)
      if (!std::isfinite(v)) return false;
    return true;
  }
};

// Templated: the camera-frame point of a board point under pose (6 values).
template <typename T>
void TransformPoint(const T* pose, const T* point, T* out) {
  ceres::AngleAxisRotatePoint(pose, point, out);
  out[0] += pose[3];
  out[1] += pose[4];
  out[2] += pose[5];
}

}  // namespace ws::calib
