// The camera models and parameter sets the model tests run on: every model
// kind, free and identifiable splines, several degrees, with and without
// tangential distortion, all shaped after the shipped Theia-like lens.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "models/camera_model.h"
#include "models/curve_fit.h"
#include "models/fisheye_lens.h"
#include "models/model_registry.h"
#include "models/theia_lens.h"

namespace ws::testing {

struct TestCamera {
  std::string name;
  CameraModel model;
  Coefficients which;  // how a calibration would see its coefficients
};

// Test names in GoogleTest's messages, not bytes.
inline void PrintTo(const TestCamera& camera, std::ostream* out) { *out << camera.name; }

// The Theia-like table in normalized radius (r = h / 1.3 mm).
inline LensTable NormalizedTheiaTable() { return ScaleLensTable(TheiaLikeLensTable(), 1 / 1.3); }

inline CameraModel WithTangential(CameraModel camera) {
  camera.fx = 350.2;
  camera.fy = 344.9;
  camera.cx = 652.3;
  camera.cy = 471.8;
  camera.p1 = 4e-4;
  camera.p2 = -3e-4;
  return camera;
}

// The Theia-like camera with D(r) replaced by a least-squares fit of `model`.
inline CameraModel TheiaFittedBy(const AnyDistortionModel& model) {
  CameraModel camera = TheiaLikeCamera();
  camera.distortion = FitByLeastSquares(model, NormalizedTheiaTable());
  return camera;
}

inline std::vector<TestCamera> TestCameras() {
  const CalibrationSetup setup{2.7, 8, 3};
  return {
      {"theia_bspline", TheiaLikeCamera(), Coefficients::kAll},
      {"theia_bspline_tangential", WithTangential(TheiaLikeCamera()), Coefficients::kAll},
      {"theia_quintic_bspline", CameraFromLensTable(TheiaLikeLensTable(), LensSensor{}, 5),
       Coefficients::kAll},
      {"identifiable_bspline",
       WithTangential(TheiaFittedBy(MakeCalibrationModel(ModelKind::kBspline, setup))),
       Coefficients::kIdentifiable},
      {"poly6", WithTangential(TheiaFittedBy(MakeCalibrationModel(ModelKind::kPoly6, setup))),
       Coefficients::kAll},
      {"poly12", WithTangential(TheiaFittedBy(MakeCalibrationModel(ModelKind::kPoly12, setup))),
       Coefficients::kAll},
  };
}

// A Kannala-Brandt camera of a 200-degree lens.
inline CameraModel Kb4Camera() {
  CameraModel camera;
  camera.image_width = 1280, camera.image_height = 960;
  camera.fx = 301.3, camera.fy = 299.2, camera.cx = 641.7, camera.cy = 477.4;
  camera.distortion = Distortion{ModelKind::kKb4, 0, {}, {-0.021, 0.0043, -0.0029, 0.00042}};
  return camera;
}

// One camera of every model kind, in ModelKinds()'s order.
inline std::vector<CameraModel> KindCameras() {
  const CalibrationSetup setup{2.7, 8, 3};
  return {WithTangential(TheiaLikeCamera()),
          WithTangential(TheiaFittedBy(MakeCalibrationModel(ModelKind::kPoly6, setup))),
          WithTangential(TheiaFittedBy(MakeCalibrationModel(ModelKind::kPoly12, setup))), Kb4Camera(),
          FisheyeKneeCamera()};
}

}  // namespace ws::testing
