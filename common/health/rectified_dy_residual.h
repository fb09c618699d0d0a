// The rectified vertical disparity of one match as a function of the
// extrinsics, for Ceres: the residual the self-repair minimises.
//
// Bouguet's rectifying rotations (cv::stereoRectify, as
// rectify/rectification.h builds them) for X_right = R X_left + T with
// R = exp([om]x):
//   r = exp(-[om/2]x)            each camera turns by half the rotation
//   t = r T,  a = t / |t|,  b = (sign t_x, 0, 0)
//   W = I + [v]x + [v]x^2 / (1 + c),  v = a x b, c = a . b
//                                 the smallest rotation taking a to b
//   R_left = W r^T,  R_right = W r
// A match's rays x_l, x_r (in each camera's frame) land at
// p_l = R_left x_l, p_r = R_right x_r, and
//   dy = f (p_r,y / p_r,z - p_l,y / p_l,z).
// Only the direction of T enters: the baseline's length changes no row.
#pragma once

#include <ceres/jet.h>
#include <ceres/rotation.h>

namespace ws {

// W x for W the smallest rotation taking unit a to b (Rodrigues' formula,
// written without the angle so that it stays smooth at a = b).
template <class T>
void AlignRotate(const T a[3], const T b[3], const T x[3], T out[3]) {
  T v[3], vx[3], vvx[3];
  ceres::CrossProduct(a, b, v);
  const T c = ceres::DotProduct(a, b);
  ceres::CrossProduct(v, x, vx);
  ceres::CrossProduct(v, vx, vvx);
  for (int i = 0; i < 3; ++i) out[i] = x[i] + vx[i] + vvx[i] / (T(1) + c);
}

// The rectified images' rows of rays x_l, x_r: y_l = p_l,y / p_l,z and
// y_r = p_r,y / p_r,z (normalised, multiply by f for pixels).
template <class T>
void RectifiedRows(const T om[3], const T t_dir[3], const T x_l[3], const T x_r[3], T* y_l, T* y_r) {
  const T half[3] = {-om[0] / T(2), -om[1] / T(2), -om[2] / T(2)};  // r = exp(half)
  const T half_inv[3] = {-half[0], -half[1], -half[2]};             // r^T
  T t[3], rl[3], rr[3], pl[3], pr[3];
  ceres::AngleAxisRotatePoint(half, t_dir, t);
  const T norm = ceres::sqrt(ceres::DotProduct(t, t));
  const T a[3] = {t[0] / norm, t[1] / norm, t[2] / norm};
  const T b[3] = {t[0] < T(0) ? T(-1) : T(1), T(0), T(0)};
  ceres::AngleAxisRotatePoint(half_inv, x_l, rl);
  ceres::AngleAxisRotatePoint(half, x_r, rr);
  AlignRotate(a, b, rl, pl);
  AlignRotate(a, b, rr, pr);
  *y_l = pl[1] / pl[2];
  *y_r = pr[1] / pr[2];
}

// Ceres functor: residual dy (pixels) of one match, parameters the angle
// axis om of R (3) and the direction of T (3, on the unit sphere).
struct RectifiedDyResidual {
  RectifiedDyResidual(const double* ray_left, const double* ray_right, double f) : f(f) {
    for (int i = 0; i < 3; ++i) {
      x_l[i] = ray_left[i];
      x_r[i] = ray_right[i];
    }
  }
  template <class T>
  bool operator()(const T* om, const T* t_dir, T* residual) const {
    const T l[3] = {T(x_l[0]), T(x_l[1]), T(x_l[2])}, r[3] = {T(x_r[0]), T(x_r[1]), T(x_r[2])};
    T y_l, y_r;
    RectifiedRows(om, t_dir, l, r, &y_l, &y_r);
    residual[0] = T(f) * (y_r - y_l);
    return true;
  }
  double x_l[3], x_r[3], f;
};

}  // namespace ws
