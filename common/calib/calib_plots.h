// PNG figures of a calibration (through common/plot, gnuplot):
//
//  - the recovered radial distortion curves D(r) of each model, one panel
//    per camera (the paper's Figs. 8-9), over the ideal radius the image
//    reaches, with the largest observed radius marked: past it a curve is
//    extrapolation (and the smoothness prior's work);
//  - the residual map: per image cell the mean residual vector (arrows
//    scaled up, the scale in the title), one panel per camera and model;
//  - the knot curve (--knots auto, issue #14): per camera the held-out and
//    the fitted RMS against the number of estimated coefficients, the
//    chosen count marked; the legend outside the plot, below it.
#pragma once

#include <string>
#include <vector>

#include "calib/calibrate.h"
#include "models/camera_model.h"

namespace ws::calib {

void WriteDistortionCurvesPng(const std::vector<StereoCalibration>& calibrations,
                              const std::string& png_path);

void WriteResidualMapPng(const std::vector<StereoCalibration>& calibrations,
                         const std::string& png_path);

// Writes nothing (returns false) when no calibration chose its knots.
bool WriteKnotCurvePng(const std::vector<StereoCalibration>& calibrations,
                       const std::string& png_path);

}  // namespace ws::calib
