// Symmetric boards: a chessboard of even x even squares looks the same
// turned by 180 degrees about its centre, so a detector may number the
// corners of one image from the opposite end. Each camera's own fit never
// notices (the view's pose takes the half-turn up), but a stereo pair whose
// right image is numbered the other way round describes no rigid rig.
//
// After the cameras' own solves, each stereo pair's relative pose
// right * left^-1 is compared with the rig's, both as detected and with the
// right image's order half-turned (board point X -> H X, H the half-turn
// about the centre of the board's extent, board_warp.h). The rig's relative
// pose is the candidate closest to the other pairs' candidates (the least
// median rotation angle to their nearest); a pair whose half-turned
// candidate is closer to it is made consistent: the right view takes the
// half-turned object points and ids (the image corners stay as detected)
// and its pose becomes pose * H. Nothing about it is fitted.
#pragma once

#include <vector>

#include "calib/mono_solve.h"
#include "calib/solver/board_warp.h"

namespace ws::calib {

// The stereo views (is_stereo) whose right image was half-turned, made
// consistent in right.prepared and right.poses. A view whose half-turned
// points are not all corners of the board (a board that is not symmetric
// as a point set) is left as it is.
std::vector<int> MakeHalfTurnsConsistent(const BoardExtent& board,
                                         const std::vector<bool>& is_stereo,
                                         const MonoState& left, MonoState* right);

}  // namespace ws::calib
