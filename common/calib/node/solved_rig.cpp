#include "calib/node/solved_rig.h"

#include "rig/rig_message.h"

namespace ws::calib {

Rig ToRig(const StereoCalibration& c) {
  Rig rig;
  rig.mono = c.mono;
  rig.left = c.left.model;
  rig.right = c.right.model;
  rig.left_rms = c.left.rms_px;
  rig.right_rms = c.right.rms_px;
  rig.left_views = c.left.views;
  rig.right_views = c.right.views;
  rig.R = c.R;
  rig.T = c.T;
  rig.rms = c.rms_px;
  rig.views = c.views;
  return rig;
}

widestereo::camera_calibration_t ToMessage(const CameraCalibration& c) {
  widestereo::camera_calibration_t msg = MessageFromCameraModel(c.model, c.name);
  msg.rms = c.rms_px;
  msg.view_rms = c.view_rms;
  msg.nviews = static_cast<int32_t>(msg.view_rms.size());
  if (c.stddev.size() == c.param_names.size()) {
    msg.param_names = c.param_names;
    msg.stddev = c.stddev;
  }
  msg.nparams = static_cast<int32_t>(msg.param_names.size());
  return msg;
}

widestereo::stereo_calibration_t ToMessage(const StereoCalibration& s, int64_t utime) {
  widestereo::stereo_calibration_t msg = MessageFromRig(ToRig(s), utime);
  msg.left = ToMessage(s.left);
  msg.right = ToMessage(s.right);
  msg.view_rms = s.view_rms;
  msg.nviews = static_cast<int32_t>(msg.view_rms.size());
  return msg;
}

}  // namespace ws::calib
