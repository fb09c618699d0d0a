// Sparse matches between the two images of a rectified pair, each located to
// a fraction of a pixel in both, with the outliers removed: what the
// calibration's health is measured from.
//
//  1. Corners: Shi-Tomasi (cv::goodFeaturesToTrack) in both images, inside
//     the part the lenses fill (eroded by `border_px`), none weaker than
//     min_strength (so that noise on a textureless scene gives none); the
//     left ones refined with cv::cornerSubPix.
//  2. Candidates: upright ORB descriptors at the corners, matched by Hamming
//     distance among the right corners in a band of rows (|dy| <=
//     search_rows, which covers the largest correction refinement accepts)
//     and of disparities (-2 <= u_left - u_right <= max_disparity); kept
//     when the best is clearly better than the second (Lowe's ratio test).
//  3. Sub-pixel: pyramidal Lucas-Kanade (cv::calcOpticalFlowPyrLK) finds
//     the left corner's point in the right image, starting from the matched
//     right corner; a point it moves more than 2 px is dropped.
//  4. Outliers: RANSAC over a smooth model of dy across the image,
//       dy = a + b x + c y + d x^2 + e x y + g y^2,  (x, y) = ((u, v) - c_rect) / f,
//     with threshold ransac_px. To first order a misalignment is such a
//     field (a rotation w of the right camera: dy = f (-w_x (1 + y^2) +
//     w_y x y + w_z x); T off the baseline: constant and linear in y for
//     a scene at one depth), so misalignment is kept and only mismatches
//     go. (An essential-matrix RANSAC would be the exact model, but it is
//     degenerate on a board or a wall: one plane.) Sampling is seeded, so a
//     replay gives the same matches.
//  5. Steps 2-4 run twice. First in a band of 3 px about dy = 0 and in the
//     whole band, keeping the one with more inliers (the whole band's when
//     the rig is off by more than 3 px); then in 3 px about the dy field
//     that one found. A repetitive pattern (a board's squares, 15 px or more apart)
//     offers a single candidate in such a band where the whole band held
//     several, and could lock onto a set of matches a square off.
#pragma once

#include <vector>

#include <opencv2/core.hpp>

#include "rectify/rectification.h"

namespace ws {

struct FeatureOptions {
  int max_corners = 1500;       // per image
  double quality = 0.01;        // Shi-Tomasi, relative to the strongest corner
  // Shi-Tomasi, absolute: cv::cornerMinEigenVal (3 x 3, grey levels as 0..1).
  // The simulator's corners (contrast 190, blur 0.6 px) reach 0.1, a corner
  // of 25 grey levels about 2e-3; noise of sigma 1 (5) grey level peaks at
  // 5e-5 (1.3e-3) over a whole 1280 x 960 image.
  double min_strength = 2e-3;
  double min_distance_px = 8;   // between corners of one image
  double border_px = 16;        // corners this far inside the filled part only
  double search_rows = 32;      // |dy| of a candidate
  double max_disparity = 320;   // px; a 0.3 m baseline at f = 347 px: 0.33 m
  double ratio = 0.8;           // Lowe's ratio on descriptor distances
  double ransac_px = 1.0;       // |dy - model| of an inlier
};

struct RectifiedMatches {
  std::vector<cv::Point2f> left, right;  // rectified pixels, one pair per match
  int corners_left = 0, corners_right = 0, candidates = 0, refined = 0;  // before each stage
};

// The part of the left (right) rectified image its lens fills, eroded by
// border_px (CV_8UC1, 255 inside): corners are taken there only, never on
// the edge of the field.
cv::Mat FilledRegion(const Rectification& rect, bool left, double border_px);

// Matches a rectified pair (CV_8UC1 both, of rect.size); filled_* are the
// FilledRegion()s of the rectification.
RectifiedMatches MatchRectifiedPair(const cv::Mat& left, const cv::Mat& right, const cv::Mat& filled_left,
                                    const cv::Mat& filled_right, const Rectification& rect,
                                    const FeatureOptions& options);

}  // namespace ws
