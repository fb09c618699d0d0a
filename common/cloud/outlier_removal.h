// The outlier stage's statistic: PCL's StatisticalOutlierRemoval, computed on
// every core. Internal to widestereo_cloud.
//
// PCL's filter runs one k-nearest-neighbour search per point on one thread,
// through pcl::KdTreeFLANN's one-query calls, and those searches are nearly
// all of the chain's time (1.6 s of 2.2 s on the benchmark's 0.3 M cloud).
// This computes the very same statistic with the same FLANN k-d tree and
// search PCL's tree wraps (15 points per leaf, exact, sorted), asking FLANN
// for thousands of points per call (a third less CPU than one call per
// point) on every core: for each point the mean
// distance to its mean_k nearest neighbours (the first result, the point
// itself, skipped as PCL does); then the mean and the sample standard
// deviation of those means, summed in point order as PCL sums them; a point
// stays when its mean distance is at most mean + stddev_mul * stddev. The
// kept indices equal PCL's (tests/cloud compare them).
#pragma once

#include <pcl/types.h>

#include "cloud/pcl_cloud.h"

namespace ws {

// The indices of the points that stay, in cloud order. The cloud must hold
// finite points only (the pass-through sees to it) and more than mean_k.
pcl::Indices StatisticalInliers(const PclCloud::Ptr& cloud, int mean_k, double stddev_mul);

}  // namespace ws
