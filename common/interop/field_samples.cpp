#include "interop/field_samples.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ws {

std::vector<FieldSample> FieldSamples(const Camera& camera, double step, double offset) {
  const CameraModel& m = camera.model();
  // Along one side: offset, offset + step, ..., and the last pixel.
  auto along = [&](int size) {
    std::vector<double> at;
    for (double x = offset; x < size - 1; x += step) at.push_back(x);
    at.push_back(size - 1);
    return at;
  };
  std::vector<FieldSample> samples;
  for (double v : along(m.image_height))
    for (double u : along(m.image_width)) {
      const Eigen::Vector2d pixel(u, v);
      const auto ray = camera.Unproject(pixel);
      if (ray && camera.InField(*ray)) samples.push_back({pixel, *ray});
    }
  return samples;
}

FitError ProjectionError(const CameraProjection& model, const std::vector<FieldSample>& samples) {
  FitError error;
  double sum = 0;
  for (const FieldSample& s : samples) {
    const auto pixel = model.Project(s.ray);
    const double d =
        pixel ? (*pixel - s.pixel).norm() : std::numeric_limits<double>::infinity();
    error.max_px = std::max(error.max_px, std::isnan(d) ? INFINITY : d);
    sum += d * d;
  }
  error.points = int(samples.size());
  if (!samples.empty()) error.rms_px = std::sqrt(sum / samples.size());
  return error;
}

}  // namespace ws
