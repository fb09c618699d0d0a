// Conversions between point_cloud_t and PCL clouds. Internal to
// widestereo_cloud: its users do not see PCL's headers.
#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include "widestereo/point_cloud_t.hpp"

namespace ws {

using PclCloud = pcl::PointCloud<pcl::PointXYZI>;

// Validates the message (ValidatePointCloud) and copies its points; intensity
// is 0 where the message has none. The result is marked not dense: it may
// hold NaN and infinite points.
PclCloud::Ptr ToPcl(const widestereo::point_cloud_t& msg);

// A message with the cloud's points and `header`'s utime, frame_id and frame;
// with intensity when `with_intensity`.
widestereo::point_cloud_t FromPcl(const PclCloud& cloud, bool with_intensity,
                                  const widestereo::point_cloud_t& header);

}  // namespace ws
