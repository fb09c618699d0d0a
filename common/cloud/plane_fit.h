// The plane stage of the stereo-cloud chain. Internal to widestereo_cloud.
#pragma once

#include <cstddef>
#include <string>

#include <Eigen/Core>

#include "cloud/pcl_cloud.h"

namespace ws {

struct PlaneFit {
  bool found = false;
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // unit; faces the camera (origin)
  double offset = 0;      // normal . x + offset = 0, so offset >= 0 is the camera's distance
  double inlier_rms = 0;  // RMS point-to-plane distance of the inliers, metres
  std::size_t inliers = 0;
  std::string note;  // why no plane was found; empty when one was
};

// RANSAC plane (SACSegmentation, SACMODEL_PLANE, inliers within `distance`
// metres) on at most ransac_points of the cloud (every k-th point; 0: all),
// then refitted by orthogonal least squares to the points of the whole cloud
// within `distance` until it stops moving. Found only with at least
// min_inliers inliers in the whole cloud; too few points, or collinear or
// identical ones, give a note. RANSAC scores each hypothesis by counting its
// inliers: a sample of tens of thousands of points ranks the hypotheses as
// the whole cloud does (the inlier fraction's sampling error is below 1 %),
// and the refit on the whole cloud sets the plane.
PlaneFit FitPlane(const PclCloud::Ptr& cloud, double distance, int max_iterations, int min_inliers,
                  int ransac_points = 0);

}  // namespace ws
