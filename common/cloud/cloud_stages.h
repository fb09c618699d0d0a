// The filtering stages of the stereo-cloud chain, over PCL. Internal to
// widestereo_cloud. Every stage copes with any cloud it can be given (empty,
// tiny, all points identical): it then passes the cloud on unchanged and says
// why in its note.
#pragma once

#include <string>

#include "cloud/pcl_cloud.h"

namespace ws {

struct StageOutput {
  PclCloud::Ptr cloud;
  std::string note;  // why the stage did not run as configured; empty when it did
};

// PassThrough on z: points with finite x, y, z and z_min <= z <= z_max.
PclCloud::Ptr KeepDepthRange(const PclCloud::Ptr& cloud, double z_min, double z_max);

// An empty cloud when every point is the same point (such a cloud has no
// shape to filter or fit, and would send outlier removal into quadratic time);
// the cloud unchanged otherwise.
StageOutput EmptyIfOnePoint(const PclCloud::Ptr& cloud);

struct VoxelOutput : StageOutput {
  double leaf = 0;  // metres: the leaf the cloud was downsampled at; 0 when it was not
};

// VoxelGrid (intensity averaged per voxel) at the leaf PlanVoxelGrid chooses.
VoxelOutput DownsampleVoxels(const PclCloud::Ptr& cloud, double leaf);

// PCL's StatisticalOutlierRemoval, on every core (outlier_removal.h); on a
// grid when voxel_leaf > 0 says the cloud is VoxelGrid's output at that leaf.
// Skipped when the cloud has no more than mean_k points (PCL would read past
// its neighbour arrays), and when it holds so many copies of the same points
// that the k-d tree search turns quadratic (200 000 identical points take
// PCL about 24 minutes: PCL issue #1146); a voxelised cloud holds none.
StageOutput RemoveOutliers(const PclCloud::Ptr& cloud, int mean_k, double stddev_mul,
                           double voxel_leaf);

}  // namespace ws
