#include "match_fixtures.h"

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

}  // namespace ws::test
