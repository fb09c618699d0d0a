// The start of an angle model's calibration (kb4, bspline_theta), where
// Zhang's homographies, which assume a pinhole, do not hold: the equidistant
// fisheye r = f theta (D = 0 over theta), which Kannala & Brandt (PAMI 2006,
// Sec. 4.2) start from, with the principal point at the image centre. The
// one unknown, f, is chosen from the data: over a geometric grid of focal
// lengths (and then a finer one about the best), every view's board pose is
// solved from the rays of its corners (ray_pose.h), and f is the value whose
// median per-view RMS is least. No focal length or field of view is assumed.
#pragma once

#include <vector>

#include "calib/solver/pose.h"
#include "calib/start/homography.h"
#include "calib/start/initialise.h"

namespace ws::calib {

// The equidistant camera {f, f, centre} ("equidistant" method) and, per
// usable view, its pose under it (poses[v] is left as is where no pose is
// found; *posed says where one is). Throws CalibrationError when no focal
// length gives a pose to at least min_views views.
PinholeInit EquidistantStart(const Prepared& prepared, int min_views, std::vector<Pose>* poses,
                             std::vector<bool>* posed);

}  // namespace ws::calib
