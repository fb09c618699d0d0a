// The figure of stereo-fit-curve: each model's fitted distortion curve over
// the table (paper Figs. 2-4) and the fitting errors against ideal height
// (Fig. 5).
#pragma once

#include <string>
#include <vector>

#include "models/curve_fit.h"
#include "models/lens_table.h"
#include "plot/plot.h"

namespace ws {

struct ModelFit {
  Distortion distortion;  // in the table's unit of height
  FitErrors errors;
};

// A human name for a fitted model: "cubic B-spline", "6th-degree polynomial".
std::string DisplayName(const Distortion& distortion);

// `unit` is the table's unit of height; errors in mm are drawn in um.
plot::Figure FitFigure(const std::string& title, const LensTable& table,
                       const std::vector<ModelFit>& fits, const std::string& unit);

}  // namespace ws
