// A complete camera: image size, pinhole intrinsics, tangential terms and a
// radial distortion model, as stored in calibration files and messages
// (CameraModel), and ready to use in double (Camera).
//
//   x = X/Z, y = Y/Z, r = sqrt(x^2 + y^2)                       (Z > 0)
//   x_d = (1 + D(r)) x + 2 p1 x y + p2 (r^2 + 2 x^2)
//   y_d = (1 + D(r)) y + p1 (r^2 + 2 y^2) + 2 p2 x y
//   u = fx x_d + cx,  v = fy y_d + cy
//
// D(r) is given by distortion.kind: bspline_distortion.h, poly_distortion.h.
// Pixel coordinates have (0, 0) at the centre of the top-left pixel.
#pragma once

#include <array>
#include <optional>

#include <Eigen/Core>

#include "models/distortion.h"
#include "models/distortion_function.h"
#include "models/pinhole_camera.h"

namespace ws {

struct CameraModel {
  int image_width = 0;
  int image_height = 0;
  double fx = 0, fy = 0, cx = 0, cy = 0;  // pixels
  double p1 = 0, p2 = 0;                  // tangential distortion
  Distortion distortion;                  // D(r), with r in normalized coordinates

  // {fx, fy, cx, cy, p1, p2}, indexed by kFx..kP2 (pinhole_camera.h).
  std::array<double, kNumIntrinsics> Intrinsics() const { return {fx, fy, cx, cy, p1, p2}; }
};

class Camera {
 public:
  // Throws std::invalid_argument unless the image size and focal lengths are
  // positive, every number is finite and the distortion is consistent.
  explicit Camera(CameraModel model);

  const CameraModel& model() const { return model_; }

  // The pixel of a camera-frame point; nullopt if Z <= 0.
  std::optional<Eigen::Vector2d> Project(const Eigen::Vector3d& point) const;
  // The unit ray (Z > 0) seen at a pixel; nullopt when the distortion cannot
  // be inverted there (see Undistort in pinhole_camera.h).
  std::optional<Eigen::Vector3d> Unproject(const Eigen::Vector2d& pixel) const;
  // D(r), the radial distortion curve: r'/r - 1 without the tangential terms.
  double DistortionCurve(double r) const { return distortion_(r); }

 private:
  CameraModel model_;
  std::array<double, kNumIntrinsics> intrinsics_;
  DistortionFunction distortion_;
};

}  // namespace ws
