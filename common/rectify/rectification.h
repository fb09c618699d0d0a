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
// Lat-lon (mrcal-stereo's rectification, for fields a plane cannot hold, 180
// degrees and beyond): in the same rectified frame (x along the baseline),
// a ray p = (x, y, z) has the elevation of its epipolar plane about the
// baseline, phi = atan2(y, z), and its azimuth within that plane,
// psi = asin(x / |p|); the rectified pixel is
//   u = cx + f psi,  v = cy + f phi      (f in pixels per radian),
// and back, the ray of (u, v) is (sin psi, cos psi sin phi, cos psi cos phi).
// Both cameras' centres lie on the baseline, so a point has the same phi,
// the same row, in both images; the disparity u_left - u_right is the angle
// psi_left - psi_right times f. f = focal_scale * min(fx, fy) as above (the
// cameras' resolution at the centre), and the image spans the common field:
// the (psi, phi) box both cameras see (each camera's pixels that unproject,
// sampled, turned into the rectified frame, their boxes intersected), or
// `size` about its centre.
//
// Maps: for every rectified pixel p, the ray R_i^T K_rect^-1 p is projected
// through camera i's own model (models/projection.h); the float maps are
// converted to OpenCV's fixed-point maps (CV_16SC2 + CV_16UC1) for cv::remap.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "rig/rig.h"

namespace ws {

// kAuto: pinhole while the rig's common field (CommonField) is at most 130
// degrees across both ways (a pinhole at the centre's resolution stretches
// the edge of a 130-degree field 5.6 times, 1 / cos^2 65 degrees; past that
// most of its image is stretched periphery), lat-lon beyond.
enum class RectificationMode { kPinhole, kLatLon, kAuto };

// "pinhole", "latlon", "auto"; throws std::invalid_argument otherwise.
RectificationMode ParseRectificationMode(const std::string& name);
const char* RectificationModeName(RectificationMode mode);

// downscale n > 1: the same rectification on a grid n times coarser, pixel
// (u', v') covering the n x n pixels of the full-resolution grid about
// (n u' + (n - 1) / 2, n v' + (n - 1) / 2): f / n, (cx + 1/2) / n - 1/2 (cy
// likewise), size / n rounded up. Its tables sample, for each grid pixel,
// the n x n full-resolution pixels it covers, and RectifyPair averages them:
// the image a full-size remap and an area downscale (cv::INTER_AREA) give,
// without the full-size image. A pixel is valid where all its samples are.
struct RectifyOptions {
  double focal_scale = 1.0;
  cv::Size size;  // empty: the input image size (pinhole), the common field (lat-lon)
  RectificationMode mode = RectificationMode::kPinhole;
  int downscale = 1;
};

struct Rectification {
  RectificationMode mode = RectificationMode::kPinhole;
  cv::Size input_size;
  cv::Size size;
  int downscale = 1;  // RectifyOptions::downscale
  cv::Matx33d R_left, R_right;  // camera frame -> rectified frame
  double f = 0, cx = 0, cy = 0;  // pinhole: K_rect; lat-lon: pixels per radian and (psi, phi) = 0
  double baseline = 0;          // metres, > 0
  cv::Matx44d Q;                // pinhole: (u, v, d, 1) -> homogeneous left-rectified point; lat-lon: 0
  // Fixed-point remap tables (cv::remap's map1, map2), one pair per sample:
  // downscale^2 of them, sample (i, j) the full-resolution pixel
  // (n u + i, n v + j) of grid pixel (u, v), in the order j, then i.
  std::vector<std::array<cv::Mat, 2>> maps_left, maps_right;
  // Per rectified pixel, 255 where it samples a pixel of the input image
  // (inside the lens's image), 0 where it does not: there the rectified
  // image holds no data (the remap's constant border), not a neighbour's.
  cv::Mat valid_left, valid_right;
  cv::Mat no_image;  // 255 where either is 0: no disparity there
  cv::Rect common;   // the bounding box of the pixels where both hold image (empty: none)
};

// Throws std::invalid_argument if the cameras' image sizes differ, the
// baseline is zero or downscale is not 1..8.
Rectification BuildRectification(const Rig& rig, const RectifyOptions& options = {});
// BuildRectification in two steps: everything but the maps and the masks
// (cheap: what the size and the checks need), then those.
Rectification RectificationGeometry(const Rig& rig, const RectifyOptions& options = {});
void BuildRectificationMaps(const Rig& rig, Rectification* rect);

// Remaps both images (any type cv::remap takes) with bilinear interpolation,
// each pixel the mean of its samples; with a region, only its pixels (the
// rest of both images is 0).
void RectifyPair(const Rectification& rect, const cv::Mat& left, const cv::Mat& right,
                 cv::Mat* left_rect, cv::Mat* right_rect, const cv::Rect& region = {});

// Where a pixel of the left (right) input image lands in the rectified
// image; false when the lens model cannot be inverted there.
bool RectifyPoint(const Rectification& rect, const Rig& rig, bool left,
                  const cv::Point2d& pixel, cv::Point2d* rectified);

// The ray of rectified pixel (u, v) in the rectified frame (the same for
// both images): K_rect^-1 (u, v, 1) (pinhole) or the lat-lon ray above.
cv::Vec3d RectifiedRay(const Rectification& rect, double u, double v);
// Back: the rectified pixel of a direction in the rectified frame; false
// when it has none (pinhole: behind the image plane).
bool RectifiedPixel(const Rectification& rect, const cv::Vec3d& direction, cv::Point2d* pixel);

// The ray, in the left (right) camera's frame, that the rectified pixel
// samples: R_i^T K_rect^-1 (u, v, 1) (pinhole) or R_i^T times the lat-lon
// ray above; not normalised.
cv::Vec3d RectifiedPixelRay(const Rectification& rect, bool left, const cv::Point2d& pixel);

// The horizontal and vertical extent (radians) of the field both cameras of
// the rig see, as lat-lon angles psi and phi in Bouguet's rectified frame.
cv::Vec2d CommonField(const Rig& rig);

}  // namespace ws
