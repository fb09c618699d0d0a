#include "wall_analysis.h"

#include <algorithm>
#include <cmath>

#include "models/camera_model.h"
#include "rectify/ray_triangulation.h"

namespace ws::test {
namespace {

bool Inside(const std::optional<Eigen::Vector2d>& pixel, const CameraModel& model) {
  return pixel && (*pixel)(0) >= 0 && (*pixel)(1) >= 0 && (*pixel)(0) <= model.image_width - 1 &&
         (*pixel)(1) <= model.image_height - 1;
}

}  // namespace

cv::Mat TrueWallDisparity(const Rectification& rect, const Rig& rig, const cv::Vec3d& normal,
                          double offset) {
  return TrueSceneDisparity(rect, rig, {cv::Vec4d(normal[0], normal[1], normal[2], offset)});
}

int FirstPlaneHit(const std::vector<cv::Vec4d>& planes, const cv::Vec3d& ray, double* scale) {
  int first = -1;
  for (size_t k = 0; k < planes.size(); ++k) {
    const double s = planes[k][3] / cv::Vec3d(planes[k][0], planes[k][1], planes[k][2]).dot(ray);
    if (s > 0 && (first < 0 || s < *scale)) first = int(k), *scale = s;
  }
  return first;
}

cv::Mat TrueSceneDisparity(const Rectification& rect, const Rig& rig, const std::vector<cv::Vec4d>& planes,
                           cv::Mat* plane_index) {
  const Camera left(rig.left), right(rig.right);
  std::vector<cv::Vec4d> rectified;  // the planes in the rectified frame
  for (const cv::Vec4d& p : planes) {
    const cv::Vec3d n = rect.R_left * cv::Vec3d(p[0], p[1], p[2]);
    rectified.emplace_back(n[0], n[1], n[2], p[3]);
  }
  cv::Mat disparity(rect.size, CV_32FC1, cv::Scalar(0));
  if (plane_index) *plane_index = cv::Mat(rect.size, CV_32SC1, cv::Scalar(-1));
  cv::parallel_for_(cv::Range(0, rect.size.height), [&](const cv::Range& rows) {
    for (int v = rows.start; v < rows.end; ++v)
      for (int u = 0; u < rect.size.width; ++u) {
        const cv::Vec3d ray = RectifiedRay(rect, u, v);
        double scale = 0;
        const int hit = FirstPlaneHit(rectified, ray, &scale);
        if (hit < 0) continue;
        const cv::Vec3d X = rect.R_left.t() * (ray * scale);  // left camera frame
        const Eigen::Vector3d Xl(X[0], X[1], X[2]);
        if (!Inside(left.Project(Xl), rig.left)) continue;
        if (!Inside(right.Project(rig.R * Xl + rig.T), rig.right)) continue;
        cv::Point2d right_pixel;  // the point seen from the right camera, at (baseline, 0, 0)
        if (!RectifiedPixel(rect, ray * scale - cv::Vec3d(rect.baseline, 0, 0), &right_pixel)) continue;
        const double d = u - right_pixel.x;
        if (u - d < 0 || !(d > 0)) continue;
        disparity.at<float>(v, u) = float(d);
        if (plane_index) plane_index->at<int>(v, u) = hit;
      }
  });
  return disparity;
}

RangeAccuracy PredictRangeAccuracy(const Rectification& rect, const cv::Mat& truth) {
  std::vector<double> changes;
  for (int v = 0; v < truth.rows; ++v)
    for (int u = 0; u < truth.cols; ++u)
      if (truth.at<float>(v, u) > 0) changes.push_back(RangeChange(rect, u, v, truth.at<float>(v, u)));
  RangeAccuracy accuracy;
  if (changes.empty()) return accuracy;
  const int col = truth.cols / 2, row = truth.rows / 2;
  if (truth.at<float>(row, col) > 0) accuracy.centre = RangeChange(rect, col, row, truth.at<float>(row, col));
  std::sort(changes.begin(), changes.end());
  accuracy.median = changes[changes.size() / 2];
  accuracy.p90 = changes[changes.size() * 9 / 10];
  return accuracy;
}

DisparityErrors CompareDisparity(const cv::Mat& disparity, const cv::Mat& truth) {
  int overlap = 0, found = 0, bad = 0, close = 0;
  double sum = 0, sum_squares = 0;
  for (int v = 0; v < truth.rows; ++v)
    for (int u = 0; u < truth.cols; ++u) {
      const float t = truth.at<float>(v, u);
      if (t <= 0) continue;
      ++overlap;
      const float d = disparity.at<float>(v, u);
      if (!(d > 0)) continue;
      ++found;
      const double error = d - t;
      if (std::abs(error) > 1) {
        ++bad;
        continue;
      }
      ++close;
      sum += error;
      sum_squares += error * error;
    }
  DisparityErrors e;
  e.density = double(found) / std::max(1, overlap);
  e.bad_rate = double(bad) / std::max(1, found);
  e.bias = sum / std::max(1, close);
  e.sigma = std::sqrt(std::max(0.0, sum_squares / std::max(1, close) - e.bias * e.bias));
  return e;
}

WallFit MeasureWall(const widestereo::point_cloud_t& cloud, const widestereo::cloud_stats_t& stats,
                    const Rectification& rect, const cv::Mat& truth, const cv::Vec3d& normal,
                    double offset, double inlier_distance, int cell) {
  WallFit fit;
  const cv::Vec3d fitted(stats.plane_normal[0], stats.plane_normal[1], stats.plane_normal[2]);
  fit.offset = stats.plane_offset;
  fit.inlier_rms = stats.inlier_rms;
  // The true normal faces away from the camera (n . X = offset > 0); the fitted one faces it.
  fit.tilt_rad = std::acos(std::min(1.0, -fitted.dot(normal)));
  const int cols = (rect.size.width + cell - 1) / cell, rows = (rect.size.height + cell - 1) / cell;
  cv::Mat covered(rows, cols, CV_8UC1, cv::Scalar(0));
  int inliers = 0;
  double sum_squares = 0;
  for (const auto& p : cloud.xyz) {
    const cv::Vec3d X(p[0], p[1], p[2]);
    const double to_truth = normal.dot(X) - offset;
    sum_squares += to_truth * to_truth;
    if (std::abs(fitted.dot(X) + stats.plane_offset) > inlier_distance) continue;
    ++inliers;
    cv::Point2d pixel;
    if (!RectifiedPixel(rect, X, &pixel)) continue;
    const int u = int(std::lround(pixel.x)), v = int(std::lround(pixel.y));
    if (u >= 0 && v >= 0 && u < rect.size.width && v < rect.size.height) covered.at<uint8_t>(v / cell, u / cell) = 1;
  }
  fit.inlier_fraction = double(inliers) / std::max<size_t>(1, cloud.xyz.size());
  fit.rms_to_truth = std::sqrt(sum_squares / std::max<size_t>(1, cloud.xyz.size()));
  int field = 0, hit = 0;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      const int u = std::min(c * cell + cell / 2, rect.size.width - 1);
      const int v = std::min(r * cell + cell / 2, rect.size.height - 1);
      if (truth.at<float>(v, u) <= 0) continue;
      ++field;
      hit += covered.at<uint8_t>(r, c);
    }
  fit.coverage = double(hit) / std::max(1, field);
  return fit;
}

}  // namespace ws::test
