#include "rectify/rectification.h"

#include <algorithm>
#include <stdexcept>

#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>
#include <opencv2/imgproc.hpp>

namespace ws {
namespace {

// Bouguet's rectifying rotations for X_right = R X_left + T.
void BouguetRotations(const StereoRig& rig, cv::Matx33d* R_left, cv::Matx33d* R_right) {
  cv::Mat R, T;
  cv::eigen2cv(rig.R, R);
  cv::eigen2cv(rig.T, T);
  const cv::Mat K = cv::Mat::eye(3, 3, CV_64F);
  cv::Mat R1, R2, P1, P2, Q;
  cv::stereoRectify(K, cv::noArray(), K, cv::noArray(), cv::Size(2, 2), R, T, R1, R2, P1, P2, Q,
                    0);
  *R_left = cv::Matx33d(R1);
  *R_right = cv::Matx33d(R2);
}

// K_rect^-1 (u, v, 1): the rectified frame's ray through pixel (u, v).
cv::Vec3d RectifiedRay(const Rectification& rect, double u, double v) {
  return {(u - rect.cx) / rect.f, (v - rect.cy) / rect.f, 1};
}

void BuildMaps(const Camera& camera, const cv::Matx33d& R_rect, const Rectification& rect,
               cv::Mat maps[2]) {
  cv::Mat map_x(rect.size, CV_32FC1), map_y(rect.size, CV_32FC1);
  const cv::Matx33d to_camera = R_rect.t();
  cv::parallel_for_(cv::Range(0, rect.size.height), [&](const cv::Range& rows) {
    for (int v = rows.start; v < rows.end; ++v) {
      float* mx = map_x.ptr<float>(v);
      float* my = map_y.ptr<float>(v);
      for (int u = 0; u < rect.size.width; ++u) {
        const cv::Vec3d ray = to_camera * RectifiedRay(rect, u, v);
        const auto pixel = camera.Project(Eigen::Vector3d(ray[0], ray[1], ray[2]));
        mx[u] = pixel ? float((*pixel)[0]) : -1.f;
        my[u] = pixel ? float((*pixel)[1]) : -1.f;
      }
    }
  });
  cv::convertMaps(map_x, map_y, maps[0], maps[1], CV_16SC2);
}

}  // namespace

Rectification BuildRectification(const StereoRig& rig, const RectifyOptions& options) {
  const Camera left(rig.left), right(rig.right);
  Rectification rect;
  rect.input_size = cv::Size(rig.left.image_width, rig.left.image_height);
  if (rect.input_size != cv::Size(rig.right.image_width, rig.right.image_height))
    throw std::invalid_argument("the two cameras of the rig have different image sizes");
  if (!(options.focal_scale > 0)) throw std::invalid_argument("focal_scale must be positive");
  rect.size = options.size.empty() ? rect.input_size : options.size;
  BouguetRotations(rig, &rect.R_left, &rect.R_right);
  rect.f = options.focal_scale * std::min({rig.left.fx, rig.left.fy, rig.right.fx, rig.right.fy});
  rect.cx = (rect.size.width - 1) / 2.0;
  rect.cy = (rect.size.height - 1) / 2.0;
  // The right camera's centre in the rectified frame is at (-baseline, 0, 0).
  const cv::Vec3d t = rect.R_right * cv::Vec3d(rig.T(0), rig.T(1), rig.T(2));
  rect.baseline = -t[0];
  if (!(rect.baseline > 0))
    throw std::invalid_argument("the right camera must be to the right of the left one (T.x < 0)");
  // Z = f b / d for disparity d = u_left - u_right (cv::reprojectImageTo3D's Q).
  rect.Q = cv::Matx44d(1, 0, 0, -rect.cx,
                       0, 1, 0, -rect.cy,
                       0, 0, 0, rect.f,
                       0, 0, 1 / rect.baseline, 0);
  BuildMaps(left, rect.R_left, rect, rect.map_left);
  BuildMaps(right, rect.R_right, rect, rect.map_right);
  return rect;
}

void RectifyPair(const Rectification& rect, const cv::Mat& left, const cv::Mat& right,
                 cv::Mat* left_rect, cv::Mat* right_rect) {
  cv::remap(left, *left_rect, rect.map_left[0], rect.map_left[1], cv::INTER_LINEAR,
            cv::BORDER_CONSTANT);
  cv::remap(right, *right_rect, rect.map_right[0], rect.map_right[1], cv::INTER_LINEAR,
            cv::BORDER_CONSTANT);
}

bool RectifyPoint(const Rectification& rect, const StereoRig& rig, bool left,
                  const cv::Point2d& pixel, cv::Point2d* rectified) {
  const Camera camera(left ? rig.left : rig.right);
  const auto ray = camera.Unproject(Eigen::Vector2d(pixel.x, pixel.y));
  if (!ray) return false;
  const cv::Vec3d p = (left ? rect.R_left : rect.R_right) * cv::Vec3d((*ray)[0], (*ray)[1], (*ray)[2]);
  if (!(p[2] > 0)) return false;
  *rectified = cv::Point2d(rect.f * p[0] / p[2] + rect.cx, rect.f * p[1] / p[2] + rect.cy);
  return true;
}

cv::Vec3d RectifiedPixelRay(const Rectification& rect, bool left, const cv::Point2d& pixel) {
  return (left ? rect.R_left : rect.R_right).t() * RectifiedRay(rect, pixel.x, pixel.y);
}

}  // namespace ws
