// The outlier stage computes PCL's StatisticalOutlierRemoval on several
// threads, by a k-d tree or, on a voxelised cloud, by a grid: either must
// keep exactly the points PCL's filter keeps.
#include <gtest/gtest.h>

#include <random>

#include <pcl/filters/statistical_outlier_removal.h>

#include "cloud/cloud_stages.h"
#include "cloud/outlier_removal.h"
#include "cloud/pcl_cloud.h"
#include "cloud_test_support.h"

namespace {

pcl::Indices PclInliers(const ws::PclCloud::Ptr& cloud, int mean_k, double stddev_mul) {
  pcl::StatisticalOutlierRemoval<pcl::PointXYZI> removal;
  removal.setInputCloud(cloud);
  removal.setMeanK(mean_k);
  removal.setStddevMulThresh(stddev_mul);
  pcl::Indices kept;
  removal.filter(kept);
  return kept;
}

// The finite points of the noisy wall scene (outliers included).
ws::PclCloud::Ptr WallWithOutliers() {
  const ws::PclCloud::Ptr all = ws::ToPcl(ws::testing::NoisyWallScene());
  ws::PclCloud::Ptr finite(new ws::PclCloud);
  for (const auto& p : *all)
    if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && p.z > 0 && p.z < 100)
      finite->push_back(p);
  return finite;
}

TEST(OutlierRemoval, KeepsExactlyThePointsPclKeeps) {
  const ws::PclCloud::Ptr wall = WallWithOutliers();
  for (int mean_k : {1, 8, 20, 50})
    for (double stddev_mul : {0.5, 1.0, 2.0}) {
      const pcl::Indices ours = ws::StatisticalInliers(wall, mean_k, stddev_mul, 0);
      EXPECT_EQ(ours, PclInliers(wall, mean_k, stddev_mul)) << mean_k << " " << stddev_mul;
      EXPECT_LT(ours.size(), wall->size());
      EXPECT_GT(ours.size(), wall->size() / 2);
    }
}

TEST(OutlierRemoval, KeepsExactlyThePointsPclKeepsInAClusteredCloud) {
  // Clusters of near-duplicates and isolated points: many equal distances.
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> box(-1, 1);
  ws::PclCloud::Ptr cloud(new ws::PclCloud);
  for (int c = 0; c < 200; ++c) {
    const float x = box(rng), y = box(rng), z = 3 + box(rng);
    for (int k = 0; k < 30; ++k) {
      pcl::PointXYZI p;
      p.x = x + 0.001f * (k % 3);
      p.y = y + 0.001f * (k / 10);
      p.z = z;
      p.intensity = 0;
      cloud->push_back(p);
    }
  }
  EXPECT_EQ(ws::StatisticalInliers(cloud, 20, 1.0, 0), PclInliers(cloud, 20, 1.0));
}

TEST(OutlierRemoval, OnVoxelsTheGridKeepsExactlyThePointsPclKeeps) {
  const ws::PclCloud::Ptr wall = WallWithOutliers();
  // Leaves coarser than the wall's 2 cm spacing (several points a voxel),
  // and finer (one a voxel: the grid must grow its cells).
  for (double leaf : {0.05, 0.03, 0.01, 0.004}) {
    const ws::VoxelOutput voxels = ws::DownsampleVoxels(wall, leaf);
    ASSERT_EQ(voxels.leaf, leaf);
    for (int mean_k : {1, 8, 20})
      for (double stddev_mul : {0.5, 2.0}) {
        const pcl::Indices ours = ws::StatisticalInliers(voxels.cloud, mean_k, stddev_mul, voxels.leaf);
        EXPECT_EQ(ours, PclInliers(voxels.cloud, mean_k, stddev_mul))
            << "leaf " << leaf << ", " << mean_k << " neighbours, " << stddev_mul;
        EXPECT_LT(ours.size(), voxels.cloud->size());
      }
  }
}

}  // namespace
