// Where a camera exported as another model is measured: its observed field,
// the pixels of its image whose ray the model has within the field it was
// calibrated over (Camera::InField), and how far another model's projection
// of those rays lands from the pixels.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "interop/camera_projection.h"

namespace ws {

struct FieldSample {
  Eigen::Vector2d pixel;
  Eigen::Vector3d ray;  // Camera::Unproject(pixel)
};

// The pixels on a grid `step` pixels apart, starting `offset` pixels in from
// the top-left pixel centre and ending on the last row and column, that are
// in the observed field, with their rays.
std::vector<FieldSample> FieldSamples(const Camera& camera, double step, double offset = 0);

struct FitError {
  double max_px = 0, rms_px = 0;
  int points = 0;
};

// |model.Project(ray) - pixel| over the samples; a ray the model cannot
// project counts as an infinite difference.
FitError ProjectionError(const CameraProjection& model, const std::vector<FieldSample>& samples);

}  // namespace ws
