// A calibration message's camera (camera_calibration_t) and a CameraModel,
// field by field: one table for both directions, so that a field the two
// carry is named once. Unchecked: lcm_io/validate.h checks the ranges and
// rig/rig_message.h makes a usable camera of it.
#pragma once

#include <algorithm>
#include <iterator>
#include <type_traits>

#include "models/camera_model.h"
#include "widestereo/camera_calibration_t.hpp"

namespace ws {

// Calls field(message's, model's) for every field the two carry alike (all
// but the model's name, the message's camera name and its list counts).
template <class Message, class Model, class Field>
void ForEachCameraMessageField(Message& msg, Model& model, Field&& field) {
  field(msg.image_width, model.image_width);
  field(msg.image_height, model.image_height);
  field(msg.fx, model.fx);
  field(msg.fy, model.fy);
  field(msg.cx, model.cx);
  field(msg.cy, model.cy);
  field(msg.p1, model.p1);
  field(msg.p2, model.p2);
  field(msg.degree, model.distortion.degree);
  field(msg.knots, model.distortion.knots);
  field(msg.coeffs, model.distortion.coeffs);
  field(msg.field_cols, model.nonradial.cols);
  field(msg.field_rows, model.nonradial.rows);
  field(msg.field_domain, model.nonradial.domain);
  field(msg.field_coeffs, model.nonradial.coeffs);
  field(msg.sensor_tilt, model.nonradial.tilt);
}

// to = from, element by element where one is a C array (the message's
// fixed arrays against the model's std::array).
template <class To, class From>
void AssignField(To& to, const From& from) {
  if constexpr (std::is_array_v<To> || std::is_array_v<From>)
    std::copy(std::begin(from), std::end(from), std::begin(to));
  else
    to = from;
}

// The message's camera as a CameraModel. Throws std::invalid_argument for an
// unknown model name, and checks nothing else.
CameraModel CameraModelFields(const widestereo::camera_calibration_t& msg);

}  // namespace ws
