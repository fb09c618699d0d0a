// The ray of every pixel corner of a camera, computed once: what the
// renderer intersects with the scene.
//
// Vertex (i, j), i = 0..W, j = 0..H, is the pixel position (i - 0.5, j - 0.5):
// the corners of the pixels, whose centres are at integer positions. Inside
// a pixel the ray is interpolated bilinearly between its four corners; the
// lens map is smooth, so this differs from the exact ray by far less than
// 0.001 px (MaxInterpolationErrorPx measures it).
//
// Unprojection: for a lens without tangential terms (p1 = p2 = 0) or a
// non-radial field the map is radial, and the ideal radius of each distorted radius is taken from a dense
// table of exact inverses (Newton on r (1 + D(r))) by cubic Hermite
// interpolation; otherwise every vertex is unprojected by Camera::Unproject.
// Vertices where the model cannot be inverted, or whose ray is more than
// max_theta off the optical axis (past the lens's image circle), hold a zero
// ray. Rays may point beyond 90 degrees (angle models).
#pragma once

#include <cmath>
#include <memory>
#include <optional>
#include <vector>

#include <opencv2/core.hpp>

#include "models/camera_model.h"

namespace ws {

class RayMap {
 public:
  explicit RayMap(const CameraModel& model, double max_theta = M_PI);
  // A shared map for `model` and `max_theta`, built on first use (a few maps are kept).
  static std::shared_ptr<const RayMap> For(const CameraModel& model, double max_theta = M_PI);

  int vertex_cols() const { return cols_; }  // W + 1
  int vertex_rows() const { return rows_; }  // H + 1
  // Unit ray at vertex (i, j); zero where the lens sees nothing.
  const cv::Vec3f& Ray(int i, int j) const { return rays_[size_t(j) * cols_ + i]; }
  bool Valid(int i, int j) const { return IsRay(Ray(i, j)); }
  static bool IsRay(const cv::Vec3f& ray) { return ray.dot(ray) > 0; }
  int invalid_count() const { return invalid_; }

  // The (not normalized) ray at pixel position (x, y) inside the image, by
  // bilinear interpolation of the vertices; nullopt next to an invalid vertex.
  std::optional<cv::Vec3d> Interpolate(double x, double y) const;

  // The largest distance, in pixels, between a pixel position and the
  // projection of its interpolated ray, over `samples` positions spread over
  // the whole image (a regular grid plus the four image corners).
  double MaxInterpolationErrorPx(const Camera& camera, int samples_per_side = 64) const;

 private:
  int cols_ = 0, rows_ = 0, invalid_ = 0;
  std::vector<cv::Vec3f> rays_;
};

// n unit rays theta off the optical axis, evenly around it: the rim of a
// lens's image circle when theta is its half field.
std::vector<Eigen::Vector3d> RaysAround(double theta, int n);

}  // namespace ws
