#include "cloud/pcd_io.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

#include <pcl/common/io.h>
#include <pcl/conversions.h>
#include <pcl/io/pcd_io.h>

#include "cloud/pcl_cloud.h"
#include "runtime/atomic_file.h"

namespace ws {
namespace {

const pcl::PCLPointField* FindField(const pcl::PCLPointCloud2& blob, const std::string& name) {
  for (const pcl::PCLPointField& field : blob.fields)
    if (field.name == name) return &field;
  return nullptr;
}

// PCL lays the fields out by the header's SIZE but reads them by their TYPE,
// without checking that the two agree: a lying header makes it read past the
// data. True when every field, read by its type, ends before the next one
// (or the end of the point) starts.
bool FieldsFitTheirPoint(const pcl::PCLPointCloud2& blob) {
  std::vector<const pcl::PCLPointField*> fields;
  for (const pcl::PCLPointField& field : blob.fields) fields.push_back(&field);
  std::sort(fields.begin(), fields.end(), [](auto* a, auto* b) { return a->offset < b->offset; });
  for (size_t i = 0; i < fields.size(); ++i) {
    const int size = pcl::getFieldSize(fields[i]->datatype);
    const uint64_t end = uint64_t(fields[i]->offset) + uint64_t(size) * fields[i]->count;
    const uint64_t next = i + 1 < fields.size() ? fields[i + 1]->offset : blob.point_step;
    if (size == 0 || end > next) return false;
  }
  return true;
}

// PCL's readHeader allocates WIDTH x HEIGHT points of SIZE x COUNT bytes
// each before it looks at the data (a COUNT of 10^70 asked for 171 GB; found
// by tests/fuzz). Throws PcdError when a header value is not a whole number
// below 10^9 or the points it announces exceed kMaxPcdBytes.
constexpr uint64_t kMaxPcdBytes = uint64_t(1) << 30;

void CheckAnnouncedSize(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  std::map<std::string, std::vector<uint64_t>> values;  // SIZE, COUNT, WIDTH, HEIGHT
  std::string line;
  while (std::getline(file, line) && line.rfind("DATA", 0) != 0) {
    std::istringstream words(line);
    std::string key, word;
    words >> key;
    if (key != "SIZE" && key != "COUNT" && key != "WIDTH" && key != "HEIGHT") continue;
    while (words >> word) {
      if (word.size() > 9 || word.find_first_not_of("0123456789") != std::string::npos)
        throw PcdError("PCD '" + path + "': " + key + " '" + word + "' is not a whole number below 10^9");
      values[key].push_back(std::stoull(word));
    }
  }
  const std::vector<uint64_t>& sizes = values["SIZE"];
  const std::vector<uint64_t>& counts = values["COUNT"];
  uint64_t point_bytes = 0, points = 1;  // each value < 10^9: no product of two overflows
  for (size_t i = 0; i < sizes.size() && point_bytes <= kMaxPcdBytes; ++i)
    point_bytes += sizes[i] * (i < counts.size() ? counts[i] : 1);
  for (const char* key : {"WIDTH", "HEIGHT"})
    if (!values[key].empty()) points *= values[key].front();
  if (point_bytes > kMaxPcdBytes || (point_bytes > 0 && points > kMaxPcdBytes / point_bytes))
    throw PcdError("PCD '" + path + "': announces " + std::to_string(points) + " points of " +
                   std::to_string(point_bytes) + " bytes, more than " + std::to_string(kMaxPcdBytes) +
                   " bytes");
}

// PCL reads a binary body without checking it against the header: a
// compressed one announcing 0 bytes made it copy points from nowhere (found
// by tests/fuzz). Throws PcdError unless the file holds the body the header
// announces: WIDTH x HEIGHT points raw, or compressed to that size.
void CheckBinaryBody(const std::string& path, const pcl::PCLPointCloud2& blob, int data_type,
                     unsigned data_idx) {
  constexpr int kBinary = 1, kBinaryCompressed = 2;
  if (data_type != kBinary && data_type != kBinaryCompressed) return;  // ASCII: read as text
  const uint64_t body_bytes = uint64_t(blob.width) * blob.height * blob.point_step;
  std::ifstream file(path, std::ios::binary | std::ios::ate);
  const uint64_t file_bytes = uint64_t(file.tellg());
  if (data_type == kBinary && file_bytes < data_idx + body_bytes)
    throw PcdError("PCD '" + path + "': " + std::to_string(file_bytes - data_idx) +
                   " bytes of data for " + std::to_string(body_bytes));
  if (data_type == kBinaryCompressed) {
    uint32_t sizes[2] = {0, 0};  // compressed, uncompressed; little-endian as PCL writes them
    file.seekg(data_idx);
    file.read(reinterpret_cast<char*>(sizes), sizeof sizes);
    if (!file || sizes[1] != body_bytes || data_idx + 8 + uint64_t(sizes[0]) > file_bytes)
      throw PcdError("PCD '" + path + "': its compressed data do not hold WIDTH x HEIGHT points");
  }
}

// What PointXYZ(I) reads: one 4-byte float.
bool IsFloat(const pcl::PCLPointField& field) {
  return field.datatype == pcl::PCLPointField::FLOAT32 && field.count == 1;
}

// The cloud with only the fields PointT has: a cloud without intensity is
// written as x y z.
template <class PointT>
pcl::PointCloud<PointT> Narrow(const PclCloud& cloud) {
  pcl::PointCloud<PointT> narrow;
  pcl::copyPointCloud(cloud, narrow);
  return narrow;
}

// The bytes of a binary PCD file of `cloud`, as PCDWriter::writeBinary lays
// them out (its header, then each point's fields packed, padding left out),
// for WriteFileAtomically.
template <class PointT>
std::string BinaryPcd(const pcl::PointCloud<PointT>& cloud) {
  std::string bytes = pcl::PCDWriter::generateHeader<PointT>(cloud) + "DATA binary\n";
  std::vector<pcl::PCLPointField> fields = pcl::getFields<PointT>();
  fields.erase(std::remove_if(fields.begin(), fields.end(), [](const auto& f) { return f.name == "_"; }),
               fields.end());
  for (const PointT& point : cloud.points)
    for (const pcl::PCLPointField& field : fields)
      bytes.append(reinterpret_cast<const char*>(&point) + field.offset,
                   size_t(pcl::getFieldSize(field.datatype)) * field.count);
  return bytes;
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

void WritePcd(const std::string& path, const PointCloud& msg) {
  const PclCloud::Ptr cloud = ToPcl(msg);
  try {
    WriteFileAtomically(path, msg.nintensity > 0 ? BinaryPcd(*cloud) : BinaryPcd(Narrow<pcl::PointXYZ>(*cloud)));
  } catch (const std::runtime_error& e) {
    throw PcdError(std::string("PCD: ") + e.what());
  }
}

PointCloud ReadPcd(const std::string& path) {
  // PCL 1.13 takes a file without a PCD header for one with no fields, and
  // its read() then crashes: look at the header first. On some malformed
  // headers it throws std::out_of_range.
  pcl::PCDReader reader;
  pcl::PCLPointCloud2 blob;
  bool with_intensity;
  PclCloud cloud;
  try {
    Eigen::Vector4f origin;
    Eigen::Quaternionf orientation;
    int version, data_type;
    unsigned data_idx;
    CheckAnnouncedSize(path);
    if (reader.readHeader(path, blob, origin, orientation, version, data_type, data_idx) != 0)
      throw PcdError("cannot read PCD '" + path + "'");
    for (const char* axis : {"x", "y", "z"}) {
      const pcl::PCLPointField* field = FindField(blob, axis);
      if (!field) throw PcdError("PCD '" + path + "' has no field '" + axis + "'");
      if (!IsFloat(*field)) throw PcdError("PCD '" + path + "': field '" + axis + "' is not one 4-byte float");
    }
    if (!FieldsFitTheirPoint(blob))
      throw PcdError("PCD '" + path + "': the fields' SIZE disagrees with their TYPE and COUNT");
    CheckBinaryBody(path, blob, data_type, data_idx);
    if (reader.read(path, blob) != 0) throw PcdError("cannot read PCD '" + path + "'");
    if (blob.data.size() != uint64_t(blob.row_step) * blob.height ||
        uint64_t(blob.point_step) * blob.width > blob.row_step)
      throw PcdError("PCD '" + path + "': its data do not hold WIDTH x HEIGHT points");
    const pcl::PCLPointField* intensity = FindField(blob, "intensity");
    with_intensity = intensity && IsFloat(*intensity);
    cloud = with_intensity ? Widen<pcl::PointXYZI>(blob) : Widen<pcl::PointXYZ>(blob);
  } catch (const PcdError&) {
    throw;
  } catch (const std::exception& e) {
    throw PcdError("cannot read PCD '" + path + "': " + e.what());
  }
  return FromPcl(cloud, with_intensity, PointCloud{});
}

}  // namespace ws
