// Choosing a voxel leaf that PCL's VoxelGrid can handle.
//
// VoxelGrid numbers voxels with 32-bit ints. When the grid over the cloud's
// bounding box would have more than 2^31 - 1 cells it prints a warning and
// returns its input unchanged; its own check casts extent / leaf to int64,
// which is undefined behaviour for huge extents; and it stores each point's
// voxel coordinate floor(x / leaf) in an int. A wide-angle stereo frustum
// easily gets there: 40 m x 40 m x 10 m at a 1 cm leaf is 1.6e10 cells.
#pragma once

#include <array>
#include <string>

namespace ws {

struct VoxelPlan {
  bool run = false;    // false: skip the voxel stage, `reason` says why
  double leaf = 0;     // metres, the requested leaf or a coarser one
  std::string reason;  // why the leaf was coarsened or the stage skipped; empty otherwise
};

// The finest leaf >= requested_leaf (metres, > 0) at which a grid over the
// axis-aligned box [min, max] fits VoxelGrid's ints; skips only when the
// box's extent overflows float, which VoxelGrid cannot handle at any leaf.
VoxelPlan PlanVoxelGrid(const std::array<float, 3>& min, const std::array<float, 3>& max,
                        double requested_leaf);

}  // namespace ws
