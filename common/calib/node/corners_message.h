// The corners of a STEREO_CORNERS message as calibration data (calib_data.h)
// and back: the LCM side of the solver's input.
#pragma once

#include <string>

#include "calib/solver/calib_data.h"
#include "widestereo/stereo_corners_t.hpp"

namespace ws::calib {

// The corners of one camera in a message (board not seen: an empty view).
BoardView ToBoardView(const widestereo::camera_corners_t& msg);
widestereo::camera_corners_t ToCornersMessage(const BoardView& view, const std::string& board_id,
                                              int image_width, int image_height);

// Adds a STEREO_CORNERS message as the next stereo view; the image sizes are
// taken from it (the first message with corners, or failing that with an
// image, sets them; a later one with corners of another size throws
// CalibrationError). A camera with no size never sent an image (a one-camera
// rig's right camera).
void AddStereoCorners(StereoData& data, const widestereo::stereo_corners_t& msg);

}  // namespace ws::calib
