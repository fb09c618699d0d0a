// Stereo rectification through the full lens model (any distortion kind).
//
// Rotations: Bouguet's, as cv::stereoRectify computes them for pinhole
// cameras — each camera turns by half the relative rotation, then both turn
// so that the baseline lies along x. Rectified pixels follow one pinhole
// K_rect = [f 0 cx; 0 f cy; 0 0 1] shared by both images:
//   f = focal_scale * min(fx, fy) over both cameras (1.0 keeps the resolution
//       at the centre; < 1 keeps more of a wide field in the same image size),
//   image size = the input size (or `size`), principal point at its centre,
//   ((w - 1) / 2, (h - 1) / 2).
// For a super-wide, low-distortion lens the input images are already close to
// pinhole, so this keeps nearly the whole field at the centre's resolution.
//
// Maps: for every rectified pixel p, the ray R_i^T K_rect^-1 p is projected
// through camera i's own model (models/projection.h); the float maps are
// converted to OpenCV's fixed-point maps (CV_16SC2 + CV_16UC1) for cv::remap.
#pragma once

#include <opencv2/core.hpp>

#include "rectify/stereo_rig.h"

namespace ws {

struct RectifyOptions {
  double focal_scale = 1.0;
  cv::Size size;  // empty: the input image size
};

struct Rectification {
  cv::Size input_size;
  cv::Size size;
  cv::Matx33d R_left, R_right;  // camera frame -> rectified frame
  double f = 0, cx = 0, cy = 0;
  double baseline = 0;          // metres, > 0
  cv::Matx44d Q;                // (u, v, d, 1) -> homogeneous left-rectified point
  cv::Mat map_left[2], map_right[2];  // fixed-point remap tables
};

// Throws std::invalid_argument if the cameras' image sizes differ or the
// baseline is zero.
Rectification BuildRectification(const StereoRig& rig, const RectifyOptions& options = {});

// Remaps both images (any type cv::remap takes) with bilinear interpolation.
void RectifyPair(const Rectification& rect, const cv::Mat& left, const cv::Mat& right,
                 cv::Mat* left_rect, cv::Mat* right_rect);

// Where a pixel of the left (right) input image lands in the rectified
// image; false when the lens model cannot be inverted there.
bool RectifyPoint(const Rectification& rect, const StereoRig& rig, bool left,
                  const cv::Point2d& pixel, cv::Point2d* rectified);

// The ray, in the left (right) camera's frame, that the rectified pixel
// samples: R_i^T K_rect^-1 (u, v, 1), not normalised.
cv::Vec3d RectifiedPixelRay(const Rectification& rect, bool left, const cv::Point2d& pixel);

}  // namespace ws
