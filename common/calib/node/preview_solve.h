// A quick solve of the views collected so far, before the first solve, for
// the live page's projection-uncertainty map (channel CALIBRATION_PREVIEW,
// a calibration_result_t): where the map is high the model is still unsure,
// and the board should go there. Quick, not the calibration: each camera on
// its own (no R, T), one model, the B-spline's knots fixed (the options'
// count, else kPreviewKnots), no cross-validation, no non-radial part, the
// board flat. The solve publishes nothing else and writes no file.
#pragma once

#include <cstdint>
#include <vector>

#include "calib/calibrate.h"
#include "widestereo/calibration_result_t.hpp"

namespace ws::calib {

inline constexpr int kPreviewKnots = 11;  // mid-ladder (kKnotLadder): a guide, not the choice

// The model a preview solves among those asked: the first angle model
// (kb4, bspline_theta), which images every ray a pinhole-radius model does
// and those at 90 degrees and beyond, so that the map comes on any lens;
// else the first asked. `models` is not empty.
ModelKind PreviewModel(const std::vector<ModelKind>& models);

// The preview of `data` under `model` (`options`' other settings): the
// model's line (RMS per camera, no held-out RMS, no stereo RMS) and each
// camera's maps, for the cameras with enough views. Throws CalibrationError
// when neither camera could be solved, Stopped on a stop request.
widestereo::calibration_result_t PreviewSolve(const StereoData& data, CalibrationOptions options, ModelKind model,
                                              int64_t utime);

}  // namespace ws::calib
