// Synthetic rigs and truth comparisons shared by the calibration tests.
#pragma once

#include <string>
#include <vector>

#include "calib/calibrate.h"
#include "synthetic_rig.h"

namespace ws::calib::test {

// ~30 stereo views of a 12 x 9 board reaching the periphery of two
// mustache-lens cameras (config/lenses/, gauge-normalised), 0.1 px noise per
// coordinate, a 12 cm baseline with a small rotation.
SyntheticRigOptions MustacheRig();
// The same kind of views through an ordinary poly6 barrel lens (~90 degrees),
// another noise draw.
SyntheticRigOptions BarrelRig();

// ~30 stereo views of the 12 x 9 board through two 200-degree knee-lens
// fisheye cameras (models/fisheye_lens.h), boards reaching 100 degrees off
// axis, 0.1 px noise, a 12 cm baseline with a small rotation.
SyntheticRigOptions FisheyeRig();

// RMS of the true cameras at the true poses on the rig's noisy corners: the
// noise floor a perfect calibration reaches.
double TruthRms(const SyntheticRigOptions& options, const SyntheticRig& rig, int camera);

// How far the estimate's projection is from the truth's over the observed
// field: every point of a 10 px lattice in each 80 x 80 px image cell holding
// at least 10 of the camera's observed corners (for an angle model, only up to
// the largest observed incidence angle: its image circle ends there).
struct ProjectionError {
  // The largest pixel distance between the truth's pixel of a ray and the
  // estimate's pixel of the same ray turned by the rotation that fits best.
  // A calibration fixes the camera frame only up to such a small rotation
  // (the board poses and R take it up; with the principal point and p1, p2
  // it is the least determined direction of the data), so this compares the
  // bundles of rays the two models see.
  double turned_px = 0;
  double direct_px = 0;     // the same without the rotation
  double rotation_rad = 0;  // the angle of that rotation
};
ProjectionError MaxProjectionError(const CameraModel& truth, const CameraModel& estimate,
                                   const CameraData& observed);

// The same at the truth's rays of the given pixels (e.g. every true corner
// of a rendered rig, issue #14): where the data are, not between them.
ProjectionError CornerRayError(const CameraModel& truth, const CameraModel& estimate,
                               const std::vector<Eigen::Vector2d>& true_pixels);

// Expects each camera of the calibration of `rig` at its noise floor (RMS
// within 10 % of TruthRms), within 0.1 px of the truth's projection over the
// observed field (MaxProjectionError) and with fx fy cx cy p1 p2 within 3
// reported sigma of the truth; prints the figures.
void ExpectCamerasMatchTruth(const SyntheticRigOptions& truth, const SyntheticRig& rig,
                             const StereoCalibration& result);

// Expects each of fx fy cx cy p1 p2 (and, when `with_coeffs`, the model's
// coefficients) of the estimate within `sigmas` reported standard deviations
// of the truth.
void ExpectParametersWithin(const CameraModel& truth, const CameraCalibration& estimate,
                            double sigmas, bool with_coeffs);
// The same for the extrinsic (rx ry rz tx ty tz).
void ExpectExtrinsicWithin(const SyntheticRigOptions& truth, const StereoCalibration& estimate,
                           double sigmas);

}  // namespace ws::calib::test
