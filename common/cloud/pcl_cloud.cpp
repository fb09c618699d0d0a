#include "cloud/pcl_cloud.h"

#include "cloud/point_cloud_check.h"

namespace ws {

PclCloud::Ptr ToPcl(const PointCloud& msg) {
  ValidatePointCloud(msg);
  PclCloud::Ptr cloud(new PclCloud);
  cloud->resize(msg.npoints);
  for (int32_t i = 0; i < msg.npoints; ++i) {
    pcl::PointXYZI& point = (*cloud)[i];
    point.x = msg.xyz[i][0];
    point.y = msg.xyz[i][1];
    point.z = msg.xyz[i][2];
    point.intensity = msg.nintensity ? msg.intensity[i] : 0.f;
  }
  cloud->is_dense = false;
  return cloud;
}

PointCloud FromPcl(const PclCloud& cloud, bool with_intensity,
                                  const PointCloud& header) {
  PointCloud msg;
  msg.utime = header.utime;
  msg.frame_id = header.frame_id;
  msg.frame = header.frame;
  msg.npoints = int32_t(cloud.size());
  msg.xyz.reserve(cloud.size());
  for (const pcl::PointXYZI& point : cloud) msg.xyz.push_back({point.x, point.y, point.z});
  msg.nintensity = with_intensity ? msg.npoints : 0;
  if (with_intensity)
    for (const pcl::PointXYZI& point : cloud) msg.intensity.push_back(point.intensity);
  return msg;
}

}  // namespace ws
