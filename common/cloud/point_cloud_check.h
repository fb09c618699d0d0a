// Consistency check of a PointCloud before any point is read.
#pragma once

#include "lcm_io/image_codec.h"  // DecodeError
#include "lcm_io/point_cloud.h"

namespace ws {

// Throws DecodeError unless npoints and nintensity are non-negative, xyz holds
// npoints points, and intensity is absent (nintensity 0) or one per point. LCM's decoder keeps the arrays and counts in step, but
// a message built in process need not.
void ValidatePointCloud(const PointCloud& msg);

}  // namespace ws
