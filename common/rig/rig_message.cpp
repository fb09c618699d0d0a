#include "rig/rig_message.h"

#include "lcm_io/camera_message_fields.h"

namespace ws {

CameraModel CameraModelFromMessage(const widestereo::camera_calibration_t& msg) {
  CameraModel model = CameraModelFields(msg);
  Camera check(model);  // throws std::invalid_argument when inconsistent
  return model;
}

Rig RigFromMessage(const widestereo::stereo_calibration_t& msg) {
  Rig rig;
  rig.left = CameraModelFromMessage(msg.left);
  rig.right = CameraModelFromMessage(msg.right);
  for (int i = 0; i < 9; ++i) rig.R(i / 3, i % 3) = msg.R[i];
  for (int i = 0; i < 3; ++i) rig.T(i) = msg.T[i];
  rig.left_rms = msg.left.rms;
  rig.right_rms = msg.right.rms;
  rig.left_views = msg.left.nviews;
  rig.right_views = msg.right.nviews;
  rig.rms = msg.rms;
  rig.views = msg.nviews;
  return rig;
}

widestereo::camera_calibration_t MessageFromCameraModel(const CameraModel& model,
                                                        const std::string& name) {
  widestereo::camera_calibration_t msg{};
  msg.name = name;
  msg.model = ModelName(model.distortion.kind);
  ForEachCameraMessageField(msg, model, [](auto& to, const auto& from) { AssignField(to, from); });
  msg.nknots = int32_t(msg.knots.size());
  msg.ncoeffs = int32_t(msg.coeffs.size());
  msg.nfield = int32_t(msg.field_coeffs.size());
  return msg;
}

widestereo::stereo_calibration_t MessageFromRig(const Rig& rig, int64_t utime) {
  widestereo::stereo_calibration_t msg{};
  msg.utime = utime;
  msg.left = MessageFromCameraModel(rig.left, "left");
  msg.right = MessageFromCameraModel(rig.right, "right");
  msg.left.rms = rig.left_rms;
  msg.right.rms = rig.right_rms;
  for (int i = 0; i < 9; ++i) msg.R[i] = rig.R(i / 3, i % 3);
  for (int i = 0; i < 3; ++i) msg.T[i] = rig.T(i);
  msg.rms = rig.rms;
  return msg;
}

}  // namespace ws
