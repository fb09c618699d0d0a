// How noisy one view's detected corners are, from the view alone: a board's
// corners lie on straight, evenly spaced rows and columns, which a lens
// bends only smoothly, so the second difference of three neighbours along a
// row or column,
//
//   e = p_{k-1} - 2 p_k + p_{k+1}                 (pixels, a 2-vector),
//
// is the detection noise (each coordinate of e has variance 6 sigma^2 for
// independent noise sigma per coordinate) plus the lens's curvature of the
// row, h^2 p'' for a spacing of h pixels. The estimate
//
//   sigma = median |e| / (sqrt(6) * sqrt(2 ln 2))
//
// (|e| is Rayleigh with scale sqrt(6) sigma, whose median is that scale
// times sqrt(2 ln 2)) is therefore the noise or, where the lens bends the
// rows strongly between neighbours, an upper bound of it. The median keeps
// a few bad corners from deciding it.
//
// stereo-calibrate uses it for what a near duplicate is (calibration_session.h):
// a board held still in a live stream moves its corners by about the noise,
// a view the person holding the board chose moves them by far more.
#pragma once

#include <vector>

#include "calib/solver/calib_data.h"

namespace ws::calib {

// The noise estimate above, pixels per coordinate; 0 when the view has no
// three neighbouring corners in a row or column.
double CornerNoise(const BoardView& view);

// The median of CornerNoise over `views`: a camera's typical detection
// noise, which a few blurred views do not decide; 0 when there are none.
double MedianCornerNoise(const std::vector<const BoardView*>& views);

}  // namespace ws::calib
