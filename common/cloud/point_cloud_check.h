// Consistency check of a point_cloud_t before any point is read.
#pragma once

#include "lcm_io/image_codec.h"  // DecodeError
#include "widestereo/point_cloud_t.hpp"

namespace ws {

// Throws DecodeError unless npoints and nintensity are non-negative, xyz holds
// npoints points of 3 coordinates each, and intensity is absent (nintensity
// 0) or one per point. LCM's decoder keeps the arrays and counts in step, but
// a message built in process need not.
void ValidatePointCloud(const widestereo::point_cloud_t& msg);

}  // namespace ws
