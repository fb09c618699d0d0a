// The stereo rig (paper Sec. VI-B and VII-B): each camera from its own
// views (mono_solve.h); then R, T and the stereo views' board poses (in the
// left camera's frame) from the views both cameras see, the cameras held
// (the paper's flow); then, in the joint flow, one solve of both cameras, R,
// T and every board pose over all views.
#pragma once

#include "calib/calibrate.h"

namespace ws::calib {

// The rig with the model of `plan`.
StereoCalibration SolveStereo(const StereoData& data, const CalibrationOptions& options,
                              const ModelPlan& plan);

}  // namespace ws::calib
