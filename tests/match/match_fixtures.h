// Calibrations and images shared by the stereo-match tests.
#pragma once

#include <string>

#include "rig/rig.h"
#include "sim/ground_truth.h"
#include "widestereo/stereo_calibration_t.hpp"

namespace ws::test {

// A distortion-free pinhole pair, R = I, T = (-baseline, 0, 0), principal
// point at the image centre: rectification is the identity for it.
widestereo::stereo_calibration_t IdentityCalibration(int width, int height, double f,
                                                     double baseline);

// The rig with both lenses described as `kind` ("poly6", "poly12") instead:
// the simulator's camera for `lens: theia, fit: KIND` (sim_config.h), i.e.
// the Theia-like design table fitted by least squares on its heights
// (models/curve_fit.h), the paper's way of comparing models. fx, fy, cx, cy,
// p1, p2, R and T are kept: the best `kind` can describe the lens, short of a
// calibration that also moves the intrinsics. The rig must have the
// simulator's default lens.
Rig RigFittedAs(const Rig& rig, const std::string& kind);

// config/sim/fisheye.yaml (the 200-degree rig) with one of its scenes
// ("wall", "room"), written as DIR/fisheye-SCENE.yaml; its path.
std::string FisheyeSceneConfig(const std::string& dir, const std::string& scene);

}  // namespace ws::test
