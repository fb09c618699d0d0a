#include "lcm_io/camera_message_fields.h"

namespace ws {

CameraModel CameraModelFields(const widestereo::camera_calibration_t& msg) {
  CameraModel model;
  model.distortion.kind = ParseModelKind(msg.model);  // throws std::invalid_argument
  ForEachCameraMessageField(msg, model, [](const auto& from, auto& to) { AssignField(to, from); });
  return model;
}

}  // namespace ws
