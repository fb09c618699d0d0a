// A board that is not flat (paper on card, a large print): mrcal's
// calobject_warp (mrcal.c, "the calibration object is a flat plane with a
// paraboloid on top"), a deflection along the board's normal
//
//   z(x, y) = x2 * 4 s (1 - s) + y2 * 4 t (1 - t),
//   s = (x - x_min) / (x_max - x_min),  t = (y - y_min) / (y_max - y_min),
//
// (x, y) a corner's flat board coordinates and [x_min, x_max] x [y_min,
// y_max] the board's extent (the bounding box of every corner the data set
// holds). z is 0 on the board's edges; x2 is the bow along x at the middle
// of an edge, and x2 + y2 the bow at the centre. z is in the board frame's
// +z direction, metres.
//
// The warp is one parameter block of 2 {x2, y2} shared by every view of the
// board (the same board in every image). Held at 0 it leaves every
// projection exactly as for a flat board.
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "calib/solver/calib_data.h"

namespace ws::calib {

struct BoardExtent {
  double x_min = 0, x_max = 1, y_min = 0, y_max = 1;
};

struct BoardWarp {
  std::array<double, 2> data{};  // x2, y2 (metres)
  BoardExtent extent;
  bool free = false;  // estimated in the solve (--board-warp), else held

  double Centre() const { return data[0] + data[1]; }
};

// How --board-warp auto decided for one camera (options.h, WarpRule::kAuto):
// the held-out RMS with the board flat and with its bow estimated, the bow
// that solve estimated with its standard deviations, and whether it was kept.
struct WarpChoice {
  bool made = false;  // false: not asked for, or too few views to cross-validate
  double flat_heldout_px = -1, warped_heldout_px = -1;
  std::array<double, 2> estimated{};  // x2, y2 (metres)
  std::vector<double> stddev;         // x2, y2; empty without covariance
  bool kept = false;
};

// The bounding box of the corners of every view of `cameras`.
BoardExtent ExtentOf(const std::vector<const CameraData*>& cameras);

// The two paraboloid terms {4 s (1 - s), 4 t (1 - t)} of a flat board point.
Eigen::Vector2d WarpBasis(const BoardExtent& extent, const Eigen::Vector3d& X);

// The board point X displaced by the warp along the board's z.
inline Eigen::Vector3d Warped(const BoardWarp& warp, const Eigen::Vector3d& X) {
  const Eigen::Vector2d b = WarpBasis(warp.extent, X);
  return X + Eigen::Vector3d(0, 0, warp.data[0] * b.x() + warp.data[1] * b.y());
}

}  // namespace ws::calib
