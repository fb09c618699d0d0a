// A calibration message's camera (camera_calibration_t) as a CameraModel,
// field by field and unchecked: what lcm_io/validate.h checks the ranges of
// and rig/rig_message.h makes a usable camera of.
#pragma once

#include "models/camera_model.h"
#include "widestereo/camera_calibration_t.hpp"

namespace ws {

// Throws std::invalid_argument for an unknown model name, and checks nothing
// else.
CameraModel CameraModelFields(const widestereo::camera_calibration_t& msg);

}  // namespace ws
