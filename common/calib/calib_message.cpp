#include "calib/calib_message.h"

#include "rectify/stereo_rig.h"

namespace ws::calib {

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
  widestereo::stereo_calibration_t msg =
      MessageFromStereoRig(StereoRig{s.left.model, s.right.model, s.R, s.T}, utime);
  msg.left = ToMessage(s.left);
  msg.right = ToMessage(s.right);
  msg.rms = s.rms_px;
  msg.view_rms = s.view_rms;
  msg.nviews = static_cast<int32_t>(msg.view_rms.size());
  return msg;
}

widestereo::stereo_calibration_t ToMessage(const CalibrationFile& f, int64_t utime) {
  widestereo::stereo_calibration_t msg = MessageFromStereoRig(StereoRig{f.left, f.right, f.R, f.T}, utime);
  msg.left.rms = f.left_rms;
  msg.right.rms = f.right_rms;
  msg.rms = f.rms;
  return msg;
}

CalibrationFile ToCalibrationFile(const widestereo::stereo_calibration_t& msg) {
  const StereoRig rig = StereoRigFromMessage(msg);
  CalibrationFile f;
  f.model = rig.left.distortion.kind;
  f.left = rig.left;
  f.right = rig.right;
  f.left_rms = msg.left.rms;
  f.right_rms = msg.right.rms;
  f.left_views = msg.left.nviews;
  f.right_views = msg.right.nviews;
  f.R = rig.R;
  f.T = rig.T;
  f.rms = msg.rms;
  f.views = msg.nviews;
  return f;
}

}  // namespace ws::calib
