// What CALIBRATION_VIEWS says of one accepted view (lcmtypes/calibration_view_t.lcm):
// its frame, its corner counts and the board's outline in each image, so that
// a viewer can draw where the board was without the image.
#pragma once

#include "widestereo/calibration_view_t.hpp"
#include "widestereo/stereo_corners_t.hpp"

namespace ws::calib {

// The view of `msg`, its RMS unknown (negative). The outline is, of the
// corners seen, the four outermost on the board (least and most x + y and
// x - y in board coordinates), in the order they go round it.
widestereo::calibration_view_t ViewSummary(const widestereo::stereo_corners_t& msg);

}  // namespace ws::calib
