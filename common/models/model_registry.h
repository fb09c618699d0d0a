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

#include <variant>

#include "models/bspline_distortion.h"
#include "models/distortion.h"
#include "models/model_kind.h"
#include "models/poly_distortion.h"

namespace ws {

using AnyDistortionModel = std::variant<BsplineDistortion, PolyDistortion<3>, PolyDistortion<6>,
                                        Kb4Distortion, BsplineThetaDistortion>;

// The alternatives are in ModelKind's order (model_kind.h): a model's index is
// its kind.
ModelKind KindOf(const AnyDistortionModel& model);

// The model of data.kind built from data's fixed part (degree, knots); the
// coefficients are not looked at. Throws std::invalid_argument for
// inconsistent data.
AnyDistortionModel MakeModel(const Distortion& data, Coefficients which);

// A fresh model of the given kind for calibration (Model::ForCalibration).
AnyDistortionModel MakeCalibrationModel(ModelKind kind, const CalibrationSetup& setup);

}  // namespace ws
