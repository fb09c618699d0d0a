// A sensor tilted in its mount, for the simulator: the image plane turned by
// tau_x about its x axis and tau_y about its y axis, through the principal
// point, as OpenCV's tilted model has it (cv::calibrateCamera's
// CALIB_TILTED_MODEL, computeTiltProjectionMatrix; the Scheimpflug
// arrangement of machine-vision cameras, here by accident of assembly):
//
//   [x'; y'; w'] = M(tau) [x_d; y_d; 1],   M(tau) = [[R33, 0, -R13], [0, R33, -R23], [0, 0, 1]] R(tau),
//   R(tau) = R_y(tau_y) R_x(tau_x),         (x_f, y_f) = (x' / w', y' / w'),
//
// so the principal ray still meets the sensor at (cx, cy). No radial curve
// describes it: the lens bends rays about the axis, the tilt stretches the
// image towards one side. The simulator draws it as a camera model's
// non-radial field (models/nonradial_field.h) of kTiltGrid control points
// across, fitted to the tilt's exact warp by least squares over the image;
// the fit is within 1e-3 px of the warp.
#pragma once

#include <array>

#include "models/camera_model.h"

namespace ws {

inline constexpr int kTiltGrid = 24;

// `model` (no field yet) with the tilt (radians) as its field; the model
// unchanged when both angles are 0. Throws std::invalid_argument when the
// fit is off the warp by 1e-3 px or more somewhere in the image.
CameraModel WithSensorTilt(const CameraModel& model, const std::array<double, 2>& tau);

}  // namespace ws
