// The ranges a camera model's numbers must lie in to be a camera's: the
// checks a calibration file (rig/rig_file.h) and a calibration message
// (lcm_io/validate.h) share, beyond Camera's consistency checks.
#pragma once

#include "models/camera_model.h"

namespace ws {

// Throws std::invalid_argument naming the first number out of range: the
// image size, finite intrinsics, knots and coefficients, focal lengths in
// [1, 1e6] px, the principal point within an image size of the image,
// |p1|, |p2| <= 1, the distortion's knots and coefficients for its kind, a
// non-radial field of 4 to 64 control points a side with coefficients of at
// most the focal length, and sensor tilts below kMaxSensorTilt.
void CheckCameraRanges(const CameraModel& camera);

}  // namespace ws
