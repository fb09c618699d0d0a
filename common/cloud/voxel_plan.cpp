#include "cloud/voxel_plan.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>

namespace ws {
namespace {

// VoxelGrid works in float; a 1% margin covers its rounding.
constexpr double kMaxIndex = 0.99 * std::numeric_limits<int32_t>::max();

// Cells of the grid along one axis, counted the way VoxelGrid sizes it
// (floor(max / leaf) - floor(min / leaf) + 1), rounded up.
double CellsAlong(double extent, double leaf) { return extent / leaf + 2; }

bool GridFits(const std::array<double, 3>& extent, double largest_coordinate, double leaf) {
  const double cells =
      CellsAlong(extent[0], leaf) * CellsAlong(extent[1], leaf) * CellsAlong(extent[2], leaf);
  return cells <= kMaxIndex && largest_coordinate / leaf + 1 <= kMaxIndex;
}

std::string Describe(const std::array<double, 3>& extent, double requested, double chosen) {
  std::ostringstream out;
  out << "leaf coarsened from " << requested << " m to " << chosen << " m: a grid over the "
      << extent[0] << " x " << extent[1] << " x " << extent[2]
      << " m bounding box would overflow VoxelGrid's 32-bit voxel indices";
  return out.str();
}

}  // namespace

VoxelPlan PlanVoxelGrid(const std::array<float, 3>& min, const std::array<float, 3>& max,
                        double requested_leaf) {
  std::array<double, 3> extent{};
  double largest_coordinate = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const float float_extent = max[axis] - min[axis];  // as VoxelGrid computes it
    if (!std::isfinite(float_extent))
      return {false, 0, "skipped: the cloud's extent overflows float"};
    extent[axis] = float_extent;
    largest_coordinate =
        std::max({largest_coordinate, std::fabs(double(min[axis])), std::fabs(double(max[axis]))});
  }
  if (GridFits(extent, largest_coordinate, requested_leaf)) return {true, requested_leaf, ""};

  // At a leaf as large as every extent and coordinate, the grid has at most
  // 3 x 3 x 3 cells; bisect (geometrically: leaves span decades) down to the
  // finest leaf that still fits.
  double too_fine = requested_leaf;
  double fits = std::max({extent[0], extent[1], extent[2], largest_coordinate});
  for (int step = 0; step < 64 && fits > too_fine * (1 + 1e-6); ++step) {
    const double middle = std::sqrt(too_fine * fits);
    (GridFits(extent, largest_coordinate, middle) ? fits : too_fine) = middle;
  }
  return {true, fits, Describe(extent, requested_leaf, fits)};
}

}  // namespace ws
