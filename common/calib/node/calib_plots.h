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
//    chosen count marked;
//  - the projection uncertainty map of each camera (issue #14).
// Every title names the rig, the camera and the model; legends sit below
// the plots, never over a curve; image axes have v growing downward.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "calib/calibrate.h"
#include "calib/evaluate/projection_diff.h"
#include "models/camera_model.h"

namespace ws::calib {

// `rig` names the rig in every figure's title.
void WriteDistortionCurvesPng(const std::vector<StereoCalibration>& calibrations,
                              const std::string& rig, const std::string& png_path);

void WriteResidualMapPng(const std::vector<StereoCalibration>& calibrations,
                         const std::string& rig, const std::string& png_path);

// Writes nothing (returns false) when no calibration chose its knots.
bool WriteKnotCurvePng(const std::vector<StereoCalibration>& calibrations,
                       const std::string& rig, const std::string& png_path);

// The projection uncertainty map (projection_uncertainty.h) of every camera
// and model, over its image, the cells with corners marked; nothing (false)
// when no camera has one.
bool WriteUncertaintyPng(const std::vector<StereoCalibration>& calibrations,
                         const std::string& rig, const std::string& png_path);

// stereo-compare's figure: each (camera name, difference) as a heat map
// over the camera's image.
void WriteProjectionDiffPng(const std::vector<std::pair<std::string, ProjectionDiff>>& cameras,
                            const std::string& title, const std::string& png_path);

}  // namespace ws::calib
