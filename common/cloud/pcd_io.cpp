#include "cloud/pcd_io.h"

#include <algorithm>

#include <pcl/common/io.h>
#include <pcl/conversions.h>
#include <pcl/io/pcd_io.h>

#include "cloud/pcl_cloud.h"

namespace ws {
namespace {

bool HasField(const pcl::PCLPointCloud2& blob, const std::string& name) {
  return std::any_of(blob.fields.begin(), blob.fields.end(),
                     [&](const pcl::PCLPointField& field) { return field.name == name; });
}

// The cloud with only the fields PointT has: a cloud without intensity is
// written as x y z.
template <class PointT>
pcl::PointCloud<PointT> Narrow(const PclCloud& cloud) {
  pcl::PointCloud<PointT> narrow;
  pcl::copyPointCloud(cloud, narrow);
  return narrow;
}

// The blob read as PointT, copied into a PclCloud (intensity 0 when PointT
// has none).
template <class PointT>
PclCloud Widen(const pcl::PCLPointCloud2& blob) {
  PclCloud cloud;
  if (blob.data.empty()) return cloud;  // fromPCLPointCloud2 would take &point[0] of no points
  pcl::PointCloud<PointT> narrow;
  pcl::fromPCLPointCloud2(blob, narrow);
  pcl::copyPointCloud(narrow, cloud);
  return cloud;
}

}  // namespace

void WritePcd(const std::string& path, const widestereo::point_cloud_t& msg) {
  const PclCloud::Ptr cloud = ToPcl(msg);
  int status;
  try {
    status = msg.nintensity > 0 ? pcl::io::savePCDFileBinary(path, *cloud)
                                : pcl::io::savePCDFileBinary(path, Narrow<pcl::PointXYZ>(*cloud));
  } catch (const pcl::IOException& e) {
    throw PcdError("cannot write PCD '" + path + "': " + e.detailedMessage());
  }
  if (status != 0) throw PcdError("cannot write PCD '" + path + "'");
}

widestereo::point_cloud_t ReadPcd(const std::string& path) {
  // PCL 1.13 takes a file without a PCD header for one with no fields, and
  // its read() then crashes: look at the header first. On some malformed
  // headers it throws std::out_of_range.
  pcl::PCDReader reader;
  pcl::PCLPointCloud2 blob;
  bool with_intensity;
  PclCloud cloud;
  try {
    if (reader.readHeader(path, blob) != 0) throw PcdError("cannot read PCD '" + path + "'");
    for (const char* axis : {"x", "y", "z"})
      if (!HasField(blob, axis)) throw PcdError("PCD '" + path + "' has no field '" + axis + "'");
    if (reader.read(path, blob) != 0) throw PcdError("cannot read PCD '" + path + "'");
    with_intensity = HasField(blob, "intensity");
    cloud = with_intensity ? Widen<pcl::PointXYZI>(blob) : Widen<pcl::PointXYZ>(blob);
  } catch (const PcdError&) {
    throw;
  } catch (const std::exception& e) {
    throw PcdError("cannot read PCD '" + path + "': " + e.what());
  }
  return FromPcl(cloud, with_intensity, widestereo::point_cloud_t{});
}

}  // namespace ws
