#include "rectify/ray_triangulation.h"

namespace ws {

std::optional<cv::Vec3d> TriangulateDisparity(const Rectification& rect, double u, double v,
                                              double d) {
  if (!(d > 0)) return std::nullopt;
  const cv::Vec3d r_l = RectifiedRay(rect, u, v), r_r = RectifiedRay(rect, u - d, v);
  const cv::Vec3d c(rect.baseline, 0, 0);
  const cv::Vec3d n = r_l.cross(r_r);
  const double n2 = n.dot(n);
  if (!(n2 > 0)) return std::nullopt;
  const double s = c.cross(r_r).dot(n) / n2;
  if (!(s > 0)) return std::nullopt;
  return s * r_l;
}

}  // namespace ws
