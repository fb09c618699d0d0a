// Fitting radial distortion models to a lens table (paper Sec. VI-A, VII-A):
// r' = (1 + D(r)) r, in the table's unit of height.
#pragma once

#include "models/distortion.h"
#include "models/lens_table.h"
#include "models/model_registry.h"

namespace ws {

// The paper's B-spline fit: clamped knots from the table's ideal heights by
// the Schoenberg-Whitney averaging (Eq. 8) and alpha from the square
// collocation system A alpha = r'/r - 1 (Eq. 9), A_ij = N_{j,K}(r_i); at
// r = 0 the right-hand side is TableDistortion's limit. The spline
// interpolates every row. Needs at least degree + 1 rows.
Distortion FitBsplineByCollocation(const LensTable& table, int degree);

// Least squares on the height residuals r'_i - r_i (1 + D(r_i)) over the
// model's coefficients, from zero, by Levenberg-Marquardt (Ceres) with the
// model's templated code. Throws std::runtime_error if the solver fails or
// the table has fewer rows than coefficients.
Distortion FitByLeastSquares(const AnyDistortionModel& model, const LensTable& table);

// Errors of a fitted r'(r) in the table's unit: at the rows (rms, max), and
// at `samples_per_interval - 1` evenly spaced heights strictly between each
// pair of rows against the monotone cubic interpolation of the table (max).
struct FitErrors {
  double rms = 0;
  double max_abs = 0;
  double max_abs_between = 0;
};
FitErrors MeasureFitErrors(const Distortion& fit, const LensTable& table,
                           int samples_per_interval = 20);

}  // namespace ws
