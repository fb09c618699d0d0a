// Conversions between PointCloud (point_cloud_t's encoding) and PCL clouds. Internal to
// widestereo_cloud: its users do not see PCL's headers.
#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include "lcm_io/point_cloud.h"

namespace ws {

using PclCloud = pcl::PointCloud<pcl::PointXYZI>;

// Validates the message (ValidatePointCloud) and copies its points; intensity
// is 0 where the message has none. The result is marked not dense: it may
// hold NaN and infinite points.
PclCloud::Ptr ToPcl(const PointCloud& msg);

// A message with the cloud's points and `header`'s utime, frame_id and frame;
// with intensity when `with_intensity`.
PointCloud FromPcl(const PclCloud& cloud, bool with_intensity,
                                  const PointCloud& header);

}  // namespace ws
