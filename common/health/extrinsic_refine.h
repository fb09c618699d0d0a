// Self-repair of the extrinsics: re-estimates the right camera's rotation
// relative to the left and the direction of T (its length kept) from
// accumulated matches, each camera's intrinsics and distortion fixed, by
// minimising the rectified vertical disparity (health/rectified_dy_residual.h)
// under a Huber loss:
//   min over om, t (|t| = 1)   sum_i huber(dy_i(om, t)^2),   R = exp([om]x), T = |T_0| t,
// solved three times, each time without the matches whose |dy| under the
// last solution exceeds max(1 px, 3 x the median) (gross mismatches, which a
// Huber loss still lets pull, e.g. a board's corners a square off).
// Guard rails: too few or too clustered matches, or a correction larger
// than max_correction_deg (of R, or of T's direction), are refused with the
// reason and change nothing.
#pragma once

#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "health/dy_figures.h"
#include "rig/rig.h"

namespace ws {

struct RayMatch {
  cv::Vec3d left, right;  // the match's rays in the left and right camera frames
  cv::Point2f pixel;      // where it is in the left rectified image (for the spread)
};

struct RefineOptions {
  int min_matches = 300;
  int min_regions = 6;          // regions of the grid ...
  int min_region_matches = 10;  // ... holding at least this many matches
  double max_correction_deg = 2;
  double loss_px = 0.5;         // Huber's scale
};

struct RefineResult {
  bool applied = false;
  std::string refused;  // why not, when not applied
  Rig rig;              // the refined rig (the input rig when refused)
  int matches = 0, matches_used = 0;  // given, and kept by the last solve
  double rotation_change_deg = 0, translation_direction_change_deg = 0;
  double dy_median_before = -1, dy_p95_before = -1;  // |dy|, px, over all the matches
  double dy_median_after = -1, dy_p95_after = -1;
};

// `f`: the rectified focal length (px) the matches were measured with;
// `size`: the rectified image size; `grid`: the regions the spread is
// counted in.
RefineResult RefineExtrinsics(const Rig& rig, double f, const std::vector<RayMatch>& matches,
                              cv::Size size, const DyGrid& grid, const RefineOptions& options);

// Median and 95th percentile of |dy| (px) of the matches under rig (R, T).
void RectifiedDyFigures(const Eigen::Matrix3d& R, const Eigen::Vector3d& T, double f,
                        const std::vector<RayMatch>& matches, double* median_abs, double* p95_abs);

}  // namespace ws
