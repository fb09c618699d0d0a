// The start of an angle model's calibration (kb4, bspline_theta), where
// Zhang's homographies, which assume a pinhole, do not hold: one of two
// one-parameter lenses, the principal point at the image centre,
//   equidistant  r = f theta       (Kannala & Brandt, PAMI 2006, Sec. 4.2)
//   perspective  r = f tan(theta)  (the pinhole)
// A fisheye past 90 degrees has no perspective image, and a lens of 120
// degrees that is rectilinear at heart has no equidistant f (its r / theta
// grows by half from the centre to the edge; with few views the best f of
// a poor fit lands anywhere). So the lens, too, is chosen from the data:
// for each lens, over a geometric grid of focal lengths (and then a finer
// one about the best), every view's board pose is solved from the rays of
// its corners (ray_pose.h); the lens and f are those whose median per-view
// RMS is least. No focal length or field of view is assumed.
#pragma once

#include <mutex>
#include <vector>

#include "calib/solver/pose.h"
#include "calib/start/initialise.h"

namespace ws::calib {

struct AngleStartFit {
  PinholeInit pinhole;  // {f, f, centre}, method "equidistant" or "perspective"
  StartLens lens = StartLens::kEquidistant;
  std::vector<Pose> poses;  // per usable view where posed, under that lens
  std::vector<bool> posed;
};

// Throws CalibrationError when no lens and focal length give a pose to at
// least min_views views. The grid's lenses are solved on every core.
AngleStartFit AngleStart(const Prepared& prepared, int min_views);

// One camera's AngleStart, solved once for the angle models that each ask
// for it on the same views (they run at once: the first to ask solves it,
// the others wait for it).
class SharedAngleStart {
 public:
  const AngleStartFit& Get(const Prepared& prepared, int min_views);

 private:
  std::once_flag once_;
  AngleStartFit fit_;
};

// Both cameras' (left, right).
struct AngleStarts {
  SharedAngleStart camera[2];
};

}  // namespace ws::calib
