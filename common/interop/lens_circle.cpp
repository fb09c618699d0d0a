#include "interop/lens_circle.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace ws {

LensCircle FindLensCircle(const Camera& camera, double observed_radius) {
  const CameraModel& m = camera.model();
  LensCircle circle;
  circle.centre = Eigen::Vector2d(m.cx, m.cy);
  constexpr int kAzimuths = 144, kSteps = 720;  // 2.5 degrees around, 0.25 degrees off the axis
  for (int a = 0; a < kAzimuths; ++a) {
    const double phi = 2 * M_PI * a / kAzimuths;
    double reached = 0;
    for (int k = 1; k < kSteps; ++k) {
      const double theta = M_PI * k / kSteps;
      const auto pixel = camera.Project(
          Eigen::Vector3d(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)));
      if (!pixel || !pixel->allFinite()) break;  // the model ends: a pinhole model at 90 degrees
      const double r = (*pixel - circle.centre).norm();
      const double ideal = camera.IsAngleModel() ? theta : std::tan(theta);
      if (!(r > reached) || ideal > observed_radius) {  // folds, or leaves the calibrated field
        circle.radius = std::min(circle.radius, reached);
        break;
      }
      reached = r;
    }
  }
  return circle;
}

std::vector<FieldSample> Within(const std::vector<FieldSample>& samples, const LensCircle& circle) {
  std::vector<FieldSample> inside;
  std::copy_if(samples.begin(), samples.end(), std::back_inserter(inside),
               [&](const FieldSample& s) { return circle.Contains(s.pixel); });
  return inside;
}

}  // namespace ws
