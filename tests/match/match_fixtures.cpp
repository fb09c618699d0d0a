#include "match_fixtures.h"

#include "sim/sim_config.h"

namespace ws::test {
namespace {

widestereo::camera_calibration_t Pinhole(const std::string& name, int width, int height, double f) {
  widestereo::camera_calibration_t c{};
  c.name = name;
  c.image_width = width;
  c.image_height = height;
  c.model = "poly6";
  c.coeffs = {0, 0, 0};
  c.ncoeffs = 3;
  c.fx = c.fy = f;
  c.cx = (width - 1) / 2.0;
  c.cy = (height - 1) / 2.0;
  return c;
}

widestereo::camera_calibration_t CameraMessage(const std::string& name, const CameraModel& model) {
  widestereo::camera_calibration_t c{};
  c.name = name;
  c.image_width = model.image_width;
  c.image_height = model.image_height;
  c.model = model.distortion.kind;
  c.degree = model.distortion.degree;
  c.knots = model.distortion.knots;
  c.nknots = int32_t(c.knots.size());
  c.coeffs = model.distortion.coeffs;
  c.ncoeffs = int32_t(c.coeffs.size());
  c.fx = model.fx;
  c.fy = model.fy;
  c.cx = model.cx;
  c.cy = model.cy;
  c.p1 = model.p1;
  c.p2 = model.p2;
  return c;
}

}  // namespace

widestereo::stereo_calibration_t IdentityCalibration(int width, int height, double f,
                                                     double baseline) {
  widestereo::stereo_calibration_t calib{};
  calib.left = Pinhole("left", width, height, f);
  calib.right = Pinhole("right", width, height, f);
  calib.R[0] = calib.R[4] = calib.R[8] = 1;
  calib.T[0] = -baseline;
  return calib;
}

StereoRig RigFromTruth(const SimTruth& truth) {
  StereoRig rig;
  rig.left = truth.left;
  rig.right = truth.right;
  for (int i = 0; i < 9; ++i) rig.R(i / 3, i % 3) = truth.R.val[i];
  for (int i = 0; i < 3; ++i) rig.T(i) = truth.T[i];
  return rig;
}

StereoRig RigFittedAs(const StereoRig& rig, const std::string& kind) {
  const SimConfig theia = ParseSimConfig(
      "rig: {baseline: 0.3, left: {lens: theia, fit: " + kind + "}}\nscene: {wall: {frames: 1}}\n",
      "the Theia-like lens fitted as " + kind, ".");
  StereoRig fitted = rig;
  fitted.left.distortion = fitted.right.distortion = theia.left.distortion;
  return fitted;
}

widestereo::stereo_calibration_t CalibrationMessage(const StereoRig& rig, int64_t utime) {
  widestereo::stereo_calibration_t calib{};
  calib.utime = utime;
  calib.left = CameraMessage("left", rig.left);
  calib.right = CameraMessage("right", rig.right);
  for (int i = 0; i < 9; ++i) calib.R[i] = rig.R(i / 3, i % 3);
  for (int i = 0; i < 3; ++i) calib.T[i] = rig.T(i);
  return calib;
}

}  // namespace ws::test
