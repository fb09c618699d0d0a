// The rig (rig/rig.h) as the STEREO_CALIBRATION message (stereo_calibration_t)
// and back. camera_calibration_t carries the full coefficient vector (for a
// B-spline alpha_0 = alpha_1 = 0 included); a rig's message carries its RMS
// figures, and no per-view RMS or parameter deviations (a solve's message
// adds them: calib/node/solved_rig.h).
#pragma once

#include <cstdint>
#include <string>

#include "models/camera_model.h"
#include "rig/rig.h"
#include "widestereo/stereo_calibration_t.hpp"

namespace ws {

// The camera model a calibration message carries. Throws std::invalid_argument
// when the message does not describe a usable camera.
CameraModel CameraModelFromMessage(const widestereo::camera_calibration_t& msg);
// The rig with its quality figures (each camera's and the stereo RMS; as
// views, the number of per-view RMS figures). Throws std::invalid_argument
// as CameraModelFromMessage.
Rig RigFromMessage(const widestereo::stereo_calibration_t& msg);

// The other way: the message of a camera model named `name` ("left",
// "right"), with no quality figures (rms 0, no views, no parameter
// deviations), and of a rig, with its RMS figures.
widestereo::camera_calibration_t MessageFromCameraModel(const CameraModel& model,
                                                        const std::string& name);
widestereo::stereo_calibration_t MessageFromRig(const Rig& rig, int64_t utime);

}  // namespace ws
