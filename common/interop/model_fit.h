// A widestereo camera as one of its simpler models, for a format that has
// no exact match of it (exact_model.h) but must hold a camera: Kalibr's
// pinhole-equi (kb4) and pinhole-radtan (poly6 with k3 = 0). All of the
// model's parameters are fitted by least squares (Ceres) to the camera's
// projection of its observed field (field_samples.h, every 8 px), starting
// from its fx, fy, cx, cy and no distortion; the error is measured on a
// grid twice as dense. The result is not the camera: the caller says so
// and prints the error.
#pragma once

#include "interop/field_samples.h"

namespace ws {

struct ModelFit {
  CameraModel model;
  FitError error;
};

// kind: "kb4", or "radtan" for poly6 with k3 = 0. Throws
// std::invalid_argument for another kind or an empty observed field.
ModelFit FitSimplerModel(const Camera& camera, const std::string& kind);

}  // namespace ws
