// Measuring a reconstructed wall against the simulator's truth (the flat-wall
// test, the paper's Sec. VII-C): where the rig can see the wall with both
// cameras, how far the matcher's disparities are from the true ones, and how
// much of that field, how flat and how far away the filtered cloud is.
#pragma once

#include <vector>

#include <opencv2/core.hpp>

#include "rectify/rectification.h"
#include "rig/rig.h"
#include "widestereo/cloud_stats_t.hpp"
#include "widestereo/point_cloud_t.hpp"

namespace ws::test {

// The wall n . X = offset (left camera frame, metres) as the true rig sees it
// through `rect`: for every left rectified pixel, the true disparity where
// the wall is seen by both cameras (its point projects inside both input
// images, and its right rectified pixel lies inside the rectified image),
// else 0 (CV_32FC1).
cv::Mat TrueWallDisparity(const Rectification& rect, const Rig& rig, const cv::Vec3d& normal,
                          double offset);

// The same for a scene of planes n . X = d (left camera frame) seen from
// inside, a box room: each ray sees the first plane ahead along it.
// *plane_index (CV_32SC1, when given): that plane's index where the
// disparity is known, else -1.
cv::Mat TrueSceneDisparity(const Rectification& rect, const Rig& rig, const std::vector<cv::Vec4d>& planes,
                           cv::Mat* plane_index = nullptr);

// The index of the first of `planes` (n . X = d) the ray from the origin
// meets ahead, and *scale, the ray's multiple that reaches it; -1 for none.
int FirstPlaneHit(const std::vector<cv::Vec4d>& planes, const cv::Vec3d& ray, double* scale);

// The predicted range change for a 0.1 px disparity error
// (ray_triangulation.h's RangeChange) over the pixels where `truth` holds a
// disparity: at the image's centre pixel (0 when it holds none), the median
// and the 90th percentile, metres.
struct RangeAccuracy {
  double centre = 0, median = 0, p90 = 0;
};
RangeAccuracy PredictRangeAccuracy(const Rectification& rect, const cv::Mat& truth);

struct DisparityErrors {
  double density = 0;   // of the overlapping pixels, those with a disparity
  double bias = 0;      // mean of d - d_true over those within 1 px, pixels
  double sigma = 0;     // RMS of d - d_true about the bias, same pixels
  double bad_rate = 0;  // of the pixels with a disparity, |d - d_true| > 1 px
};
DisparityErrors CompareDisparity(const cv::Mat& disparity, const cv::Mat& truth);

struct WallFit {
  double offset = 0;          // distance of the fitted plane from the camera, metres
  double tilt_rad = 0;        // angle between the fitted and the true normal
  double inlier_rms = 0;      // stereo-cloud's plane-fit RMS, metres
  double inlier_fraction = 0; // of the filtered cloud, the plane's inliers
  double rms_to_truth = 0;    // RMS distance of every filtered point from the true wall, metres
  double coverage = 0;        // of the overlapping field (cells), the part holding plane inliers
};

// The filtered cloud (left rectified frame) and its stats against the true
// wall (normal and offset in the rectified frame). Coverage counts
// cell x cell pixel cells of the rectified image whose centre is in the
// overlapping field (`truth` > 0) and which hold a point within
// `inlier_distance` of the fitted plane.
WallFit MeasureWall(const widestereo::point_cloud_t& cloud, const widestereo::cloud_stats_t& stats,
                    const Rectification& rect, const cv::Mat& truth, const cv::Vec3d& normal,
                    double offset, double inlier_distance, int cell = 8);

}  // namespace ws::test
