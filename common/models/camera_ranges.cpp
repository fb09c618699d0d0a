#include "models/camera_ranges.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "models/image_size.h"
#include "models/sensor_tilt.h"

namespace ws {
namespace {

void Require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument(what);
}

template <class Range>
bool AllFinite(const Range& values) {
  return std::all_of(std::begin(values), std::end(values),
                     [](double v) { return std::isfinite(v); });
}

constexpr double kMaxFocalPx = 1e6;
constexpr double kMinFocalPx = 1;  // a focal length under a pixel is no camera's (fx = 1e-300 gave f = 0 px)
constexpr double kMaxCoefficient = 1e8;

}  // namespace

void CheckCameraRanges(const CameraModel& c) {
  const Distortion& d = c.distortion;
  const NonRadial& field = c.nonradial;
  Require(ImageSizeAcceptable(c.image_width, c.image_height),
          "bad image size " + std::to_string(c.image_width) + "x" + std::to_string(c.image_height));
  Require(AllFinite(d.knots) && AllFinite(d.coeffs), "non-finite knots or coefficients");
  Require(std::all_of(d.coeffs.begin(), d.coeffs.end(), [](double k) { return std::abs(k) <= kMaxCoefficient; }),
          "a distortion coefficient beyond 1e8 (no lens's: the model's arithmetic loses every digit)");
  Require(std::is_sorted(d.knots.begin(), d.knots.end()), "knots are not non-decreasing");
  Require(AllFinite(c.Intrinsics()), "non-finite intrinsics");
  // Bounds no real camera comes near; beyond them the model's arithmetic
  // loses every digit (a 1e270 px focal length was found by tests/fuzz).
  Require(c.fx >= kMinFocalPx && c.fy >= kMinFocalPx && c.fx <= kMaxFocalPx && c.fy <= kMaxFocalPx,
          "fx and fy must be in [1, " + std::to_string(int(kMaxFocalPx)) + "] pixels");
  Require(c.cx >= -c.image_width && c.cx <= 2.0 * c.image_width && c.cy >= -c.image_height &&
              c.cy <= 2.0 * c.image_height,
          "the principal point (cx, cy) lies more than an image size outside the image");
  Require(std::abs(c.p1) <= 1 && std::abs(c.p2) <= 1, "|p1| and |p2| must be at most 1");
  (void)DistortionFunction(d);  // every kind of the model table: its knots and number of coefficients
  // The non-radial field: none, or a grid of its coefficients over a
  // rectangle; a correction of more than the focal length is no lens's.
  const size_t grid = 2 * size_t(std::max(field.cols, 0)) * size_t(std::max(field.rows, 0));
  Require((field.cols == 0 && field.rows == 0 && field.coeffs.empty()) ||
              (field.cols >= 4 && field.rows >= 4 && field.cols <= NonRadialField::kMaxControlPoints &&
               field.rows <= NonRadialField::kMaxControlPoints && field.coeffs.size() == grid),
          "a non-radial field has 4 to 64 control points a side and 2 cols rows coefficients");
  Require(AllFinite(field.domain) && AllFinite(field.coeffs), "non-finite non-radial field");
  Require(field.coeffs.empty() || (field.domain[1] > field.domain[0] && field.domain[3] > field.domain[2]),
          "empty non-radial field rectangle");
  Require(std::all_of(field.coeffs.begin(), field.coeffs.end(), [](double k) { return std::abs(k) <= 1; }),
          "a non-radial field coefficient beyond 1 (the focal length)");
  Require(std::all_of(field.tilt.begin(), field.tilt.end(),
                      [](double tau) { return std::abs(tau) < kMaxSensorTilt; }),
          "a sensor tilt angle not below kMaxSensorTilt (0.35 rad) or not finite");
}

}  // namespace ws
