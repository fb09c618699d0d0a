// A widestereo camera as one of its simpler models, for a format that has
// no exact match of it (exact_model.h) but must hold a camera: Kalibr's
// pinhole-equi (kb4) and pinhole-radtan (poly6 with k3 = 0). All of the
// model's parameters are fitted by least squares (Ceres) to the camera's
// projection of its observed field (field_samples.h, every 8 px) within a
// lens circle (lens_circle.h: where the lens sees, as the mrcal export is
// fitted), starting from its fx, fy, cx, cy and no distortion; the error is
// measured on a grid twice as dense, within the circle and over the whole
// observed field. The result is not the camera: the caller says so and
// prints both errors.
#pragma once

#include "interop/field_samples.h"
#include "interop/lens_circle.h"

namespace ws {

struct ModelFit {
  CameraModel model;
  FitError error;        // over the observed field within the circle, where it was fitted
  FitError image_error;  // over the whole observed field
};

// kind: "kb4", or "radtan" for poly6 with k3 = 0; circle: where to fit (the
// default holds every pixel). Throws std::invalid_argument for another kind
// or an empty observed field within the circle.
ModelFit FitSimplerModel(const Camera& camera, const std::string& kind, const LensCircle& circle = {});

}  // namespace ws
