// Board poses fitted one view at a time with the camera held fixed: how the
// stages of a calibration bring every view's pose up to the camera as it
// stands, and recover views whose pose fell into the wrong basin.
#pragma once

#include <string>
#include <vector>

#include "calib/solver/camera_block.h"
#include "calib/solver/problem.h"
#include "calib/start/initialise.h"

namespace ws::calib {

// Fits the pose of one view from *pose on the corners of `mask`, the camera
// and the board's shape (board_warp.h; flat by default) fixed; returns the
// view's RMS, or infinity (and *pose unchanged) when the fit fails.
double RefinePose(const CameraBlock& camera, const BoardView& view, const std::vector<char>& mask,
                  Pose* pose, const BoardWarp& warp = BoardWarp());

// Both planar PnP solutions (IPPE) of the view's corners in mask, undistorted
// by the camera; none when fewer than 4 corners can be undistorted. For an
// angle model, whose rays may pass 90 degrees, the pose from the rays
// (ray_pose.h) instead.
std::vector<Pose> PlanarPoseCandidates(const CameraBlock& camera, const BoardView& view,
                                       const std::vector<char>& mask);

// Refits the pose of every usable view with at least min_points_per_view
// corners in `mask` (from its homography first when from_homography). A
// board seen obliquely or far off axis has a second, mirrored pose that a
// local fit can fall into, and a pose fitted to part of a board can put its
// other corners behind the camera: views fitting ten times worse than the
// median (and above 2 px) start again from both IPPE solutions and their
// homography, keeping the best. A view that still fits that badly but
// reaches past the field the fitting views cover is kept with the pose of
// its corners inside that field, when those fit and the model can take the
// rest (the outermost board of a wide lens, which the camera only
// extrapolates to). Returns, per view, false for the others.
std::vector<bool> RefitPoses(const CameraBlock& camera, const Prepared& prepared, const Init& init,
                             const Inliers& mask, bool from_homography,
                             const CalibrationOptions& options, const std::string& what,
                             std::vector<Pose>* poses);

}  // namespace ws::calib
