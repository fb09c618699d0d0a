#include "rectify/ray_triangulation.h"

#include <cmath>

namespace ws {

std::optional<cv::Vec3d> TriangulateDisparity(const Rectification& rect, double u, double v,
                                              double d) {
  if (!(d > 0)) return std::nullopt;
  if (rect.mode == RectificationMode::kLatLon) {
    // The same intersection in closed form (the law of sines in the
    // epipolar plane): four sines and cosines instead of eight and two cross products.
    const double psi_l = (u - rect.cx) / rect.f, phi = (v - rect.cy) / rect.f, angle = d / rect.f;
    const double s = rect.baseline * std::cos(psi_l - angle) / std::sin(angle);
    if (!(s > 0) || !std::isfinite(s)) return std::nullopt;
    const double c = std::cos(psi_l);
    return cv::Vec3d(std::sin(psi_l), c * std::sin(phi), c * std::cos(phi)) * s;
  }
  const cv::Vec3d r_l = RectifiedRay(rect, u, v), r_r = RectifiedRay(rect, u - d, v);
  const cv::Vec3d c(rect.baseline, 0, 0);
  const cv::Vec3d n = r_l.cross(r_r);
  const double n2 = n.dot(n);
  if (!(n2 > 0)) return std::nullopt;
  const double s = c.cross(r_r).dot(n) / n2;
  if (!(s > 0)) return std::nullopt;
  return s * r_l;
}

namespace {

// The angle of a rectified ray from the epipolar plane's normal to the baseline.
double Psi(const cv::Vec3d& ray) { return std::asin(ray[0] / cv::norm(ray)); }

// dpsi/du at rectified pixel (u, v).
double PsiPerPixel(const Rectification& rect, double u, double v) {
  if (rect.mode == RectificationMode::kLatLon) return 1 / rect.f;
  const double a = (u - rect.cx) / rect.f, b = (v - rect.cy) / rect.f;
  const double w2 = 1 + b * b;
  return std::sqrt(w2) / (w2 + a * a) / rect.f;
}

}  // namespace

double RangeChange(const Rectification& rect, double u, double v, double d, double error) {
  if (!(d > 0)) return NAN;
  const double psi_l = Psi(RectifiedRay(rect, u, v)), psi_r = Psi(RectifiedRay(rect, u - d, v));
  const double s = std::sin(psi_l - psi_r);
  return rect.baseline * std::cos(psi_l) / (s * s) * PsiPerPixel(rect, u - d, v) * error;
}

}  // namespace ws
