// PlanVoxelGrid keeps PCL's VoxelGrid inside its 32-bit voxel indices.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>

#include "cloud/voxel_plan.h"

namespace {

constexpr double kIntMax = std::numeric_limits<int32_t>::max();

// The cells VoxelGrid allocates: floor(max / leaf) - floor(min / leaf) + 1 per axis.
double GridCells(const std::array<float, 3>& min, const std::array<float, 3>& max, double leaf) {
  double cells = 1;
  for (int axis = 0; axis < 3; ++axis)
    cells *= std::floor(max[axis] / leaf) - std::floor(min[axis] / leaf) + 1;
  return cells;
}

TEST(VoxelPlan, KeepsALeafThatFits) {
  const auto plan = ws::PlanVoxelGrid({-2, -1.5f, 0.3f}, {2, 1.5f, 6}, 0.01);
  EXPECT_TRUE(plan.run);
  EXPECT_EQ(plan.leaf, 0.01);
  EXPECT_TRUE(plan.reason.empty());
}

TEST(VoxelPlan, CoarsensToTheFinestLeafThatFits) {
  // A 125-degree frustum out to 10 m: about 38 x 38 x 9.7 m.
  const std::array<float, 3> min{-19.2f, -19.2f, 0.3f}, max{19.2f, 19.2f, 10};
  ASSERT_GT(GridCells(min, max, 0.01), kIntMax);
  const auto plan = ws::PlanVoxelGrid(min, max, 0.01);
  ASSERT_TRUE(plan.run);
  EXPECT_LE(GridCells(min, max, plan.leaf), kIntMax);
  EXPECT_GT(GridCells(min, max, plan.leaf * 0.97), kIntMax);  // within the 1 % margin + 2 %
  EXPECT_EQ(plan.reason.rfind("leaf coarsened from 0.01 m to ", 0), 0) << plan.reason;
}

TEST(VoxelPlan, CoarsensWhenCoordinatesOverflowIntAlthoughTheBoxIsSmall) {
  const std::array<float, 3> min{1e7f, 0, 2}, max{1e7f + 1, 1, 3};
  const auto plan = ws::PlanVoxelGrid(min, max, 0.001);
  ASSERT_TRUE(plan.run);
  EXPECT_LT(1e7 / plan.leaf, kIntMax);
  EXPECT_GT(plan.leaf, 0.001);
}

TEST(VoxelPlan, SkipsWhenTheExtentOverflowsFloat) {
  const auto plan = ws::PlanVoxelGrid({-3e38f, 0, 1}, {3e38f, 1, 2}, 0.01);
  EXPECT_FALSE(plan.run);
  EXPECT_EQ(plan.reason, "skipped: the cloud's extent overflows float");
}

}  // namespace
