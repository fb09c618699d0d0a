// Every distortion model the system knows, in one place.
//
// Solvers and processes work on AnyDistortionModel with std::visit, e.g.
//
//   std::visit([&](const auto& model) {
//     using Model = std::decay_t<decltype(model)>;
//     ... ReprojectionResidual<Model>{model, ...} ...
//   }, MakeCalibrationModel(kind, setup));
//
// so they are written once for all models. To add a model, write its header
// following the concept in distortion.h and add its class to the variant below.
#pragma once

#include <string>
#include <variant>
#include <vector>

#include "models/bspline_distortion.h"
#include "models/distortion.h"
#include "models/poly_distortion.h"

namespace ws {

using AnyDistortionModel = std::variant<BsplineDistortion, PolyDistortion<3>, PolyDistortion<6>,
                                        Kb4Distortion, BsplineThetaDistortion>;

// The kinds of the models above, in that order: "bspline", "poly6", "poly12",
// "kb4", "bspline_theta".
std::vector<std::string> ModelKinds();

// The model of data.kind built from data's fixed part (degree, knots); the
// coefficients are not looked at. Throws std::invalid_argument for an unknown
// kind or inconsistent data.
AnyDistortionModel MakeModel(const Distortion& data, Coefficients which);

// A fresh model of the given kind for calibration (Model::ForCalibration).
AnyDistortionModel MakeCalibrationModel(const std::string& kind, const CalibrationSetup& setup);

// Whether the model's r is the incidence angle theta (kb4, bspline_theta)
// rather than tan(theta) (radial_coordinate.h).
bool IsAngleModel(const AnyDistortionModel& model);
// Whether p1, p2 apply (every model but kb4).
bool HasTangential(const AnyDistortionModel& model);

// The name of a kind's coefficient vector in calibration files and reports:
// "alpha" for the B-splines, "k" for the polynomials. Throws
// std::invalid_argument for an unknown kind.
std::string CoefficientKey(const std::string& kind);

}  // namespace ws
