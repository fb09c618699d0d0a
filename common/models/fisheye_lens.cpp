#include "models/fisheye_lens.h"

#include <cmath>

#include "models/curve_fit.h"
#include "models/model_registry.h"

namespace ws {

LensTable FisheyeKneeLensTable() {
  LensTable table;
  for (int i = 0; i <= 180; ++i) {
    const double theta = 0.01 * i;
    const double s = 0.08 * std::log1p(std::exp((theta - 1.3) / 0.08));
    table.ideal.push_back(theta);
    table.real.push_back(theta * (1 - 0.06 * theta * theta + 0.25 * s * s));
  }
  return table;
}

CameraModel FisheyeKneeCamera() {
  CameraModel camera;
  camera.image_width = 1280;
  camera.image_height = 960;
  camera.fx = camera.fy = 300;
  camera.cx = 639.5;
  camera.cy = 479.5;
  camera.distortion = FitByLeastSquares(
      MakeCalibrationModel(ModelKind::kBsplineTheta, CalibrationSetup{1.8, 16, 3}), FisheyeKneeLensTable());
  return camera;
}

}  // namespace ws
