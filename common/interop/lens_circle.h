// Where a calibrated camera's lens sees, as its model says: the circle
// about the principal point within which the model images each direction
// once. Along every azimuth the model's pixel moves outwards as the ray
// leaves the axis, up to where its radial map folds: past that, rays land
// back on pixels nearer the centre, which no lens does within its image
// circle. A fisheye model carried beyond its lens (a calibration's knots
// span the whole image, black corners and all, where no corner was seen)
// folds there or soon after, and another tool's model fitted over the fold
// bends to follow what the lens never imaged. The circle's radius is the
// smallest fold over the azimuths: the model, not a constant, says where
// its lens ends. A model that rises all the way (a pinhole model to 90
// degrees, most kb4) has no fold, and its circle holds the whole image,
// unless the calibration's report bounds it.
#pragma once

#include <cmath>
#include <vector>

#include <Eigen/Core>

#include "interop/field_samples.h"
#include "models/camera_model.h"

namespace ws {

struct LensCircle {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();  // the principal point
  double radius = INFINITY;                          // pixels; infinite: no fold
  bool Contains(const Eigen::Vector2d& pixel) const { return (pixel - centre).norm() <= radius; }
};

// Along 144 azimuths, rays every quarter degree off the axis up to straight
// back, projected until the distance from the principal point stops growing
// or, when the calibration says how far out it saw corners (its report's
// max_observed_radius: the ideal radius, radial_coordinate.h, of its
// outermost inlier corner), the ray goes past that: the circle is then the
// smaller of the fold and the calibrated field.
LensCircle FindLensCircle(const Camera& camera, double observed_radius = INFINITY);

// The samples within the circle.
std::vector<FieldSample> Within(const std::vector<FieldSample>& samples, const LensCircle& circle);

}  // namespace ws
