#include "interop/field_samples.h"

#include <algorithm>
#include <cmath>

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
  error.points = int(samples.size());
  for (const FieldSample& s : samples) {
    const auto pixel = model.Project(s.ray);
    const double d = pixel && pixel->allFinite() ? (*pixel - s.pixel).norm() : INFINITY;
    error.max_px = std::max(error.max_px, d);
    error.rms_px += d * d;  // the sum of squares until the end
  }
  if (error.points > 0) error.rms_px = std::sqrt(error.rms_px / error.points);
  return error;
}

}  // namespace ws
