// How well a calibrated camera predicts views it was not fitted to
// (BabelCalib's train/test protocol, Lochman et al. 2021, Sec. 5): the
// camera held fixed, each view's board pose fitted alone to its corners, and
// the RMS of all those corners' residuals.
#pragma once

#include <vector>

#include "calib/board_warp.h"
#include "calib/calib_data.h"
#include "calib/camera_block.h"
#include "models/camera_model.h"

namespace ws::calib {

struct HeldOutFit {
  double rms_px = 0;             // over every corner of the posed views
  int views = 0;                 // views a pose was found for
  int points = 0;
  std::vector<double> view_rms;  // per view; negative where no pose fits
};

// A stored camera as the solver's block (its estimated coefficients), fixed.
CameraBlock FixedBlock(const CameraModel& model);

// Every non-empty view with at least min_points corners posed under the
// fixed camera and board shape (a calibration's board_warp; flat by
// default): from each planar start (pose_fit.h), refined, the best kept.
HeldOutFit FitHeldOutViews(const CameraModel& camera, const CameraData& views, int min_points = 6,
                           const BoardWarp& warp = BoardWarp());

}  // namespace ws::calib
