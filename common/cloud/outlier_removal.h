// The outlier stage's statistic: PCL's StatisticalOutlierRemoval, computed on
// every core. Internal to widestereo_cloud.
//
// For each point the mean distance to its mean_k nearest neighbours (the
// first result, the point itself, skipped as PCL does); then the mean and
// the sample standard deviation of those means, summed in point order as
// PCL sums them; a point stays when its mean distance is at most
// mean + stddev_mul * stddev. The kept indices equal PCL's (tests/cloud
// compare them).
//
// PCL's filter runs one k-d tree search per point on one thread, and those
// searches are nearly all of the chain's time. Two searches here find the
// same neighbour distances to the bit, on every core:
// - on a voxelised cloud, a grid of cells (neighbour_grid.h): three
//   quarters of the k-d tree's CPU time on a cloud stereo-match published
//   live, about the same on bench/cloud's noisier made-up ones;
// - on any other cloud, where the points per cell would be unbounded, the
//   FLANN k-d tree and search PCL's tree wraps (15 points per leaf, exact,
//   sorted), asked for thousands of points per call.
#pragma once

#include <pcl/types.h>

#include "cloud/pcl_cloud.h"

namespace ws {

// The indices of the points that stay, in cloud order. The cloud must hold
// finite points only (the pass-through sees to it) and more than mean_k.
// voxel_leaf: metres, > 0 when the cloud holds at most one point per voxel
// of that edge (VoxelGrid's output): the grid search; 0: the k-d tree.
pcl::Indices StatisticalInliers(const PclCloud::Ptr& cloud, int mean_k, double stddev_mul,
                                double voxel_leaf);

}  // namespace ws
