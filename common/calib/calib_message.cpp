#include "calib/calib_message.h"

namespace ws::calib {

widestereo::camera_calibration_t ToMessage(const CameraCalibration& c) {
  const CameraModel& m = c.model;
  widestereo::camera_calibration_t msg;
  msg.name = c.name;
  msg.image_width = m.image_width;
  msg.image_height = m.image_height;
  msg.model = m.distortion.kind;
  msg.degree = m.distortion.degree;
  msg.knots = m.distortion.knots;
  msg.nknots = static_cast<int32_t>(msg.knots.size());
  msg.coeffs = m.distortion.coeffs;
  msg.ncoeffs = static_cast<int32_t>(msg.coeffs.size());
  msg.fx = m.fx;
  msg.fy = m.fy;
  msg.cx = m.cx;
  msg.cy = m.cy;
  msg.p1 = m.p1;
  msg.p2 = m.p2;
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
  widestereo::stereo_calibration_t msg;
  msg.utime = utime;
  msg.left = ToMessage(s.left);
  msg.right = ToMessage(s.right);
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) msg.R[3 * r + c] = s.R(r, c);
    msg.T[r] = s.T(r);
  }
  msg.rms = s.rms_px;
  msg.view_rms = s.view_rms;
  msg.nviews = static_cast<int32_t>(msg.view_rms.size());
  return msg;
}

}  // namespace ws::calib
