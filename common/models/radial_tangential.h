// The radial + tangential distortion shared by every model (paper Eq. 6):
//
//   x_d = (1 + D) x + 2 p1 x y + p2 (r^2 + 2 x^2)
//   y_d = (1 + D) y + p1 (r^2 + 2 y^2) + 2 p2 x y
//
// where D = D(r) is the model's radial distortion at r = sqrt(x^2 + y^2).
#pragma once

namespace ws {

template <typename T>
void RadialTangential(const T& radial, const T& p1, const T& p2, const T& x, const T& y, T* xd,
                      T* yd) {
  const T xy = x * y;
  const T x2 = x * x;
  const T y2 = y * y;
  const T r2 = x2 + y2;
  const T scale = 1.0 + radial;
  *xd = scale * x + 2.0 * p1 * xy + p2 * (r2 + 2.0 * x2);
  *yd = scale * y + p1 * (r2 + 2.0 * y2) + 2.0 * p2 * xy;
}

}  // namespace ws
