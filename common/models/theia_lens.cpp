#include "models/theia_lens.h"

#include <sstream>

#include "models/curve_fit.h"

namespace ws {

// The text of config/lenses/theia-my125m-like.csv (theia_lens_table.cpp.in).
const char* TheiaLikeLensCsv();

LensTable TheiaLikeLensTable() {
  std::istringstream csv(TheiaLikeLensCsv());
  return ParseLensTable(csv, "config/lenses/theia-my125m-like.csv", TableColumns::kRealHeight);
}

CameraModel CameraFromLensTable(const LensTable& table_mm, const LensSensor& sensor, int degree) {
  CameraModel camera;
  camera.image_width = sensor.image_width;
  camera.image_height = sensor.image_height;
  camera.fx = camera.fy = sensor.focal_length_mm / sensor.pixel_pitch_mm;
  camera.cx = sensor.image_width / 2.0;
  camera.cy = sensor.image_height / 2.0;
  camera.distortion =
      FitBsplineByCollocation(ScaleLensTable(table_mm, 1.0 / sensor.focal_length_mm), degree);
  return camera;
}

CameraModel TheiaLikeCamera() { return CameraFromLensTable(TheiaLikeLensTable(), LensSensor{}); }

}  // namespace ws
