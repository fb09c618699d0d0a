#include "lcm_io/camera_fields.h"

#include <algorithm>

namespace ws {

CameraModel CameraModelFields(const widestereo::camera_calibration_t& msg) {
  CameraModel model;
  model.image_width = msg.image_width;
  model.image_height = msg.image_height;
  model.fx = msg.fx;
  model.fy = msg.fy;
  model.cx = msg.cx;
  model.cy = msg.cy;
  model.p1 = msg.p1;
  model.p2 = msg.p2;
  model.distortion.kind = ParseModelKind(msg.model);  // throws std::invalid_argument
  model.distortion.degree = msg.degree;
  model.distortion.knots = msg.knots;
  model.distortion.coeffs = msg.coeffs;
  model.nonradial.cols = msg.field_cols;
  model.nonradial.rows = msg.field_rows;
  std::copy(msg.field_domain, msg.field_domain + 4, model.nonradial.domain.begin());
  model.nonradial.coeffs = msg.field_coeffs;
  std::copy(msg.sensor_tilt, msg.sensor_tilt + 2, model.nonradial.tilt.begin());
  return model;
}

}  // namespace ws
