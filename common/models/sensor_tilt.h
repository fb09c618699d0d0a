// A sensor tilted in its mount: the image plane turned by tau_x about its x
// axis and tau_y about its y axis through the principal point, exactly as
// OpenCV's tilted model (cv::calibrateCamera's CALIB_TILTED_MODEL,
// computeTiltProjectionMatrix; the Scheimpflug arrangement of machine-vision
// cameras, here by accident of assembly):
//
//   R(tau) = R_y(tau_y) R_x(tau_x),
//   R_x = [1 0 0; 0 cx sx; 0 -sx cx],  R_y = [cy 0 -sy; 0 1 0; sy 0 cy]
//        (cx = cos tau_x, sx = sin tau_x, cy = cos tau_y, sy = sin tau_y),
//   M(tau) = [R22 0 -R02; 0 R22 -R12; 0 0 1] R(tau)
//          = [cx 0 0; -sx sy cy 0; sy -cy sx cy cx],
//   [x'; y'; w'] = M(tau) [x_d; y_d; 1],   (x_t, y_t) = (x' / w', y' / w').
//
// The distorted point (x_d, y_d) of the lens becomes the tilted point
// (x_t, y_t) on the sensor; the principal ray still meets it at (0, 0).
// To first order x_t = x_d (1 - tau_y x_d + tau_x y_d), and likewise y_t:
// the image stretched towards one side, which no radial curve describes. On
// a pinhole lens this is a turn of the camera with a shift of the principal
// point; only the lens's distortion, bent about the optical axis, tells
// the two apart.
#pragma once

#include <cmath>

namespace ws {

// The largest tilt a camera model accepts, each angle (radians, 20 degrees):
// far past any sensor mounted by accident, short of where M(tau) turns
// the image's edge towards the horizon.
inline constexpr double kMaxSensorTilt = 0.35;

// The tilted point of the distorted point d[2]; tau = {tau_x, tau_y} in
// radians. T may be a ceres::Jet in tau, in d or both.
template <typename A, typename T>
void TiltPoint(const A* tau, const T* d, T* tilted) {
  using std::cos;
  using std::sin;
  const A cx = cos(tau[0]), sx = sin(tau[0]), cy = cos(tau[1]), sy = sin(tau[1]);
  const T w = sy * d[0] - cy * sx * d[1] + cy * cx;
  tilted[0] = cx * d[0] / w;
  tilted[1] = (cy * d[1] - sx * sy * d[0]) / w;
}

// The distorted point of the tilted point t[2] (M(tau) inverted); false
// where it has none (behind the tilted plane's horizon).
inline bool UntiltPoint(const double* tau, const double* t, double* d) {
  const double cx = std::cos(tau[0]), sx = std::sin(tau[0]), cy = std::cos(tau[1]),
               sy = std::sin(tau[1]);
  // M^-1 [t; 1] up to scale; M is lower triangular: forward substitution
  // of M [a; b; c] = [t0; t1; 1] with c free, taken as 1 after scaling.
  // Rows: cx a = t0 w; -sx sy a + cy b = t1 w; sy a - cy sx b + cy cx = w.
  // With a = t0 w / cx, b = (t1 w + sx sy a) / cy, the third row gives w.
  const double a1 = t[0] / cx, b1 = (t[1] + sx * sy * a1) / cy;  // a = a1 w, b = b1 w
  const double denominator = 1 - sy * a1 + cy * sx * b1;
  if (!(denominator > 0) || !std::isfinite(denominator)) return false;
  const double w = cy * cx / denominator;
  d[0] = a1 * w;
  d[1] = b1 * w;
  return true;
}

}  // namespace ws
