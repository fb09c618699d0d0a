// Calibrations and images shared by the stereo-match tests.
#pragma once

#include <string>

#include "models/camera_model.h"
#include "rectify/stereo_rig.h"
#include "sim/ground_truth.h"
#include "widestereo/stereo_calibration_t.hpp"

namespace ws::test {

// A distortion-free pinhole pair, R = I, T = (-baseline, 0, 0), principal
// point at the image centre: rectification is the identity for it.
widestereo::stereo_calibration_t IdentityCalibration(int width, int height, double f,
                                                     double baseline);

// The simulator's true rig (both camera models, R, T).
StereoRig RigFromTruth(const SimTruth& truth);

// `camera` with its lens refitted as `kind` ("poly6", "poly12"): the
// Theia-like design table (the simulator's default lens, models/theia_lens.h)
// fitted by least squares on its heights (models/curve_fit.h), the paper's
// way of comparing models, with fx, fy, cx, cy, p1, p2 kept. For a camera of
// that lens it is the best `kind` can describe it, short of a calibration that
// also moves the intrinsics.
CameraModel WithTheiaLensFittedAs(const CameraModel& camera, const std::string& kind);

// Both cameras of the rig refitted as `kind` (WithTheiaLensFittedAs), R and T kept.
StereoRig RigFittedAs(const StereoRig& rig, const std::string& kind);

// The STEREO_CALIBRATION message of a rig (stamped `utime`).
widestereo::stereo_calibration_t CalibrationMessage(const StereoRig& rig, int64_t utime);

}  // namespace ws::test
