#include "rig/rig_message.h"

#include "lcm_io/camera_fields.h"

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
  msg.image_width = model.image_width;
  msg.image_height = model.image_height;
  msg.model = ModelName(model.distortion.kind);
  msg.degree = model.distortion.degree;
  msg.knots = model.distortion.knots;
  msg.nknots = int32_t(msg.knots.size());
  msg.coeffs = model.distortion.coeffs;
  msg.ncoeffs = int32_t(msg.coeffs.size());
  msg.fx = model.fx;
  msg.fy = model.fy;
  msg.cx = model.cx;
  msg.cy = model.cy;
  msg.p1 = model.p1;
  msg.p2 = model.p2;
  msg.field_cols = model.nonradial.cols;
  msg.field_rows = model.nonradial.rows;
  std::copy(model.nonradial.domain.begin(), model.nonradial.domain.end(), msg.field_domain);
  msg.field_coeffs = model.nonradial.coeffs;
  msg.nfield = int32_t(msg.field_coeffs.size());
  std::copy(model.nonradial.tilt.begin(), model.nonradial.tilt.end(), msg.sensor_tilt);
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
