#include "rectify/stereo_rig.h"

#include "calib/calib_file.h"
#include "models/camera_model.h"

namespace ws {

CameraModel CameraModelFromMessage(const widestereo::camera_calibration_t& msg) {
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
  Camera check(model);  // throws std::invalid_argument when inconsistent
  return model;
}

StereoRig StereoRigFromMessage(const widestereo::stereo_calibration_t& msg) {
  StereoRig rig;
  rig.left = CameraModelFromMessage(msg.left);
  rig.right = CameraModelFromMessage(msg.right);
  for (int i = 0; i < 9; ++i) rig.R(i / 3, i % 3) = msg.R[i];
  for (int i = 0; i < 3; ++i) rig.T(i) = msg.T[i];
  return rig;
}

StereoRig StereoRigFromFile(const std::string& path) {
  const calib::CalibrationFile file = calib::ReadCalibrationFile(path);
  if (file.mono)
    throw calib::CalibrationFileError(path + ": a one-camera calibration (no right camera, no "
                                      "stereo): a stereo rig is needed");
  StereoRig rig;
  rig.left = file.left;
  rig.right = file.right;
  rig.R = file.R;
  rig.T = file.T;
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

widestereo::stereo_calibration_t MessageFromStereoRig(const StereoRig& rig, int64_t utime) {
  widestereo::stereo_calibration_t msg{};
  msg.utime = utime;
  msg.left = MessageFromCameraModel(rig.left, "left");
  msg.right = MessageFromCameraModel(rig.right, "right");
  for (int i = 0; i < 9; ++i) msg.R[i] = rig.R(i / 3, i % 3);
  for (int i = 0; i < 3; ++i) msg.T[i] = rig.T(i);
  return msg;
}

}  // namespace ws
