// A camera's fields, named once (docs/calibration-file.md). The calibration
// file (rig/camera_fields.h), the report's cameras (calib/node/report.h) and
// Python's Camera.parameters write a CameraModel by walking this table, and
// the message's mapping (lcm_io/camera_message_fields.h) is checked against
// it field by field (tests/lcm_io), so a field added here reaches every one.
//
//   image_width, image_height     pixels
//   fx, fy, cx, cy                pixels (the calibration file holds them as
//                                 OpenCV's camera_matrix)
//   model                         the model's name (models/model_registry.h)
//   degree                        B-spline degree (0 for the polynomials)
//   knots                         the clamped knot vector: the splines only
//   alpha or k                    the radial coefficients, under the model's key
//   p1, p2                        tangential distortion
//   nonradial                     only where the camera has a field or a tilt:
//     cols, rows, domain, coeffs    the field's grid (models/nonradial_field.h)
//     tilt                          tau_x, tau_y, radians: only where tilted
#pragma once

#include "models/camera_model.h"
#include "models/model_kind.h"

namespace ws {

// visit(key, value) for each of the non-radial map's fields it holds.
template <class Visit>
void ForEachNonRadialField(const NonRadial& f, Visit&& visit) {
  if (f.cols > 0) {
    visit("cols", f.cols);
    visit("rows", f.rows);
    visit("domain", f.domain);
    visit("coeffs", f.coeffs);
  }
  if (f.tilted()) visit("tilt", f.tilt);
}

// visit(key, value) for each field of the camera in the table's order:
// value an int, a double, a ModelKind, a std::vector<double>, a
// std::array<double, N> or the NonRadial map (ForEachNonRadialField).
template <class Visit>
void ForEachCameraField(const CameraModel& m, Visit&& visit) {
  const ModelTraits& traits = Traits(m.distortion.kind);
  visit("image_width", m.image_width);
  visit("image_height", m.image_height);
  visit("fx", m.fx);
  visit("fy", m.fy);
  visit("cx", m.cx);
  visit("cy", m.cy);
  visit("model", m.distortion.kind);
  visit("degree", m.distortion.degree);
  if (traits.spline) visit("knots", m.distortion.knots);
  visit(traits.coeff_key, m.distortion.coeffs);
  visit("p1", m.p1);
  visit("p2", m.p2);
  if (!m.nonradial.empty()) visit("nonradial", m.nonradial);
}

}  // namespace ws
