#include "room_analysis.h"

#include <cmath>

#include "cloud/cloud_filter.h"
#include "wall_analysis.h"

namespace ws::test {

RoomField TrueRoomField(const Rig& rig, const std::vector<cv::Vec4d>& planes) {
  RoomField field;
  field.latlon = BuildRectification(rig, RectifyOptions{1.0, {}, RectificationMode::kLatLon});
  field.disparity = TrueSceneDisparity(field.latlon, rig, planes, &field.face);
  for (const cv::Vec4d& p : planes) {
    const cv::Vec3d n = field.latlon.R_left * cv::Vec3d(p[0], p[1], p[2]);
    field.planes.emplace_back(n[0], n[1], n[2], p[3]);
  }
  return field;
}

RoomFit MeasureRoom(const widestereo::point_cloud_t& cloud, const RoomField& field,
                    const CloudFilterConfig& config, int cell) {
  const Rectification& rect = field.latlon;
  const int cols = (rect.size.width + cell - 1) / cell, rows = (rect.size.height + cell - 1) / cell;
  cv::Mat covered(rows, cols, CV_8UC1, cv::Scalar(0));
  std::vector<PointCloud> on_face(field.planes.size());
  for (const auto& p : cloud.xyz) {
    const cv::Vec3d X(p[0], p[1], p[2]);
    double scale = 0;
    const int face = FirstPlaneHit(field.planes, X, &scale);
    if (face >= 0) on_face[size_t(face)].xyz.push_back({p[0], p[1], p[2]});
    cv::Point2d left, right;
    if (!RectifiedPixel(rect, X, &left) || !RectifiedPixel(rect, X - cv::Vec3d(rect.baseline, 0, 0), &right))
      continue;
    const int u = int(std::lround(left.x)), v = int(std::lround(left.y));
    if (u < 0 || v < 0 || u >= rect.size.width || v >= rect.size.height) continue;
    const float truth = field.disparity.at<float>(v, u);
    if (truth > 0 && std::abs(left.x - right.x - truth) <= 1) covered.at<uint8_t>(v / cell, u / cell) = 1;
  }
  RoomFit fit;
  fit.faces.resize(field.planes.size());
  int in_field = 0, hit = 0;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      const int u = std::min(c * cell + cell / 2, rect.size.width - 1);
      const int v = std::min(r * cell + cell / 2, rect.size.height - 1);
      const int face = field.face.at<int>(v, u);
      if (face < 0) continue;
      ++in_field;
      hit += covered.at<uint8_t>(r, c);
      fit.faces[size_t(face)].field_fraction += 1;
    }
  fit.coverage = double(hit) / std::max(1, in_field);
  CloudFilterConfig plane_only = config;
  plane_only.z_min = -1e6;  // every point: the faces lie all around the camera
  plane_only.z_max = 1e6;
  plane_only.voxel_enabled = plane_only.outliers_enabled = false;
  plane_only.plane_enabled = true;
  const CloudFilter filter(plane_only);
  for (size_t k = 0; k < field.planes.size(); ++k) {
    FaceFit& face = fit.faces[k];
    face.field_fraction /= std::max(1, in_field);
    face.true_offset = field.planes[k][3];
    on_face[k].npoints = int32_t(on_face[k].xyz.size());
    face.points = on_face[k].npoints;
    if (face.points < config.plane_min_inliers) continue;
    const CloudFilterResult result = filter.Run(on_face[k]);
    face.found = result.stats.plane_found;
    if (!face.found) continue;
    const cv::Vec3d normal(result.stats.plane_normal[0], result.stats.plane_normal[1], result.stats.plane_normal[2]);
    const cv::Vec3d truth(field.planes[k][0], field.planes[k][1], field.planes[k][2]);
    face.offset = result.stats.plane_offset;
    face.inlier_rms = result.stats.inlier_rms;
    // The fitted normal faces the camera, the true one faces away.
    face.tilt_rad = std::acos(std::min(1.0, -normal.dot(truth)));
  }
  return fit;
}

std::string FaceName(const cv::Vec4d& plane) {
  static const char* names[3][2] = {{"right (+x)", "left (-x)"}, {"floor (+y)", "ceiling (-y)"},
                                    {"front (+z)", "back (-z)"}};
  int axis = 0;
  for (int a = 1; a < 3; ++a)
    if (std::abs(plane[a]) > std::abs(plane[axis])) axis = a;
  return names[axis][plane[axis] > 0 ? 0 : 1];
}

}  // namespace ws::test
