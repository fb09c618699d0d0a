// Calibrations and images shared by the stereo-match tests.
#pragma once

#include <string>

#include "rectify/stereo_rig.h"
#include "widestereo/stereo_calibration_t.hpp"

namespace ws::test {

// A distortion-free pinhole pair, R = I, T = (-baseline, 0, 0), principal
// point at the image centre: rectification is the identity for it.
widestereo::stereo_calibration_t IdentityCalibration(int width, int height, double f,
                                                     double baseline);

}  // namespace ws::test
