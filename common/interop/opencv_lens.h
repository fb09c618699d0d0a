// OpenCV's full pinhole lens model (cv::projectPoints; mrcal's
// LENSMODEL_OPENCV4/5/8/12 are its first 4, 5, 8 and 12 coefficients):
//
//   x = X/Z, y = Y/Z, r^2 = x^2 + y^2
//   D = (1 + k1 r^2 + k2 r^4 + k3 r^6) / (1 + k4 r^2 + k5 r^4 + k6 r^6) - 1
//   x_d = (1 + D) x + 2 p1 x y + p2 (r^2 + 2 x^2) + s1 r^2 + s2 r^4
//   y_d = (1 + D) y + p1 (r^2 + 2 y^2) + 2 p2 x y + s3 r^2 + s4 r^4
//   u = fx x_d + cx,  v = fy y_d + cy
//
// As a model class of distortion.h's concept (Coordinate, NumCoeffs,
// RadialDistortion, Distort), so that models/projection.h projects and
// inverts it: the coefficients are {k1, k2, k3, k4, k5, k6, s1, s2, s3, s4}
// (unused ones 0), p1 and p2 are the intrinsics' own. Only 4 and 5
// coefficients are one of widestereo's models (poly6); the rational and thin
// prism terms are not, so a calibration with them is compared through this.
#pragma once

#include <algorithm>
#include <vector>

#include "models/camera_model.h"
#include "models/radial_coordinate.h"
#include "models/radial_tangential.h"

namespace ws {

class OpenCvLens {
 public:
  using Coordinate = TanTheta;
  static constexpr int kNumCoeffs = 10;

  int NumCoeffs() const { return kNumCoeffs; }

  template <typename T>
  T RadialDistortion(const T* k, const T& r) const {
    return OfSquaredRadius(k, r * r);
  }

  template <typename T>
  void Distort(const T* k, const T& p1, const T& p2, const T& x, const T& y, T* xd, T* yd) const {
    const T r2 = x * x + y * y;
    RadialTangential(OfSquaredRadius(k, r2), p1, p2, x, y, xd, yd);
    *xd += (k[6] + k[7] * r2) * r2;
    *yd += (k[8] + k[9] * r2) * r2;
  }

 private:
  template <typename T>
  static T OfSquaredRadius(const T* k, const T& r2) {
    return (1.0 + r2 * (k[0] + r2 * (k[1] + r2 * k[2]))) /
               (1.0 + r2 * (k[3] + r2 * (k[4] + r2 * k[5]))) -
           1.0;
  }
};

// OpenCV's D as widestereo's poly6 into `m` (its distortion, p1, p2 and
// tilt): 4 or 5 coefficients k1 k2 p1 p2 [k3], or the 14 of
// CALIB_TILTED_MODEL with only k1 k2 p1 p2 k3 and the tilt tauX tauY set.
// False for another count, or 14 with a rational or thin-prism term
// (k4..k6, s1..s4), which poly6 has not.
inline bool OpenCvPoly6(const std::vector<double>& d, CameraModel* m) {
  if (d.size() != 4 && d.size() != 5 && d.size() != 14) return false;
  if (d.size() == 14 && std::any_of(d.begin() + 5, d.begin() + 12, [](double v) { return v != 0; })) return false;
  m->distortion = Distortion{ModelKind::kPoly6, 0, {}, {d[0], d[1], d.size() > 4 ? d[4] : 0.0}};
  m->p1 = d[2], m->p2 = d[3];
  if (d.size() == 14) m->nonradial.tilt = {d[12], d[13]};
  return true;
}

}  // namespace ws
