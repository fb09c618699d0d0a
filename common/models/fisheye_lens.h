// The project's fisheye test lens: a 200-degree lens whose curve has a knee
// in the incidence angle theta (the fisheye analogue of the paper's mustache,
// which a Kannala-Brandt polynomial can only approach), as a "bspline_theta"
// camera of 1280 x 960 pixels whose image circle fits inside the image.
//
//   r_d(theta) = theta (1 + D(theta)),
//   D(theta) = -0.06 theta^2 + 0.25 s(theta)^2,
//   s(theta) = 0.08 log(1 + exp((theta - 1.3) / 0.08))   (a knee at 74.5 degrees)
//
// in radians; f = 300 px, so 100 degrees off axis lands 455 px from the
// centre. The camera holds the gauge a calibration uses (D(0) = D'(0) = 0):
// an identifiable cubic spline on 16 uniform spans over [0, 1.8 rad] fitted
// to the curve by least squares, within 0.004 px of it over the field.
#pragma once

#include "models/camera_model.h"
#include "models/lens_table.h"

namespace ws {

// The curve at 181 angles from 0 to 1.8 rad (ideal = theta, real = r_d).
LensTable FisheyeKneeLensTable();

// The camera: fx = fy = 300, c = (639.5, 479.5), no tangential terms.
CameraModel FisheyeKneeCamera();

}  // namespace ws
