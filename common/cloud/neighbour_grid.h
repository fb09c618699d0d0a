// Exact k-nearest-neighbour distances on a voxelised cloud by a uniform grid.
// Internal to widestereo_cloud.
//
// A k-d tree pays a descent and a backtrack per query, nearly all of the
// outlier stage's time. VoxelGrid's output holds at most one point per
// leaf^3, so a grid of cells a few leaves wide holds a bounded number of
// points per cell, and the nearest neighbours of a point lie in the cube of
// 3^3 cells about its own. The points of one cell share that cube: its
// points are gathered once into flat arrays and every query of the cell
// runs through them in one vectorised loop, and only those within a limit
// (the previous query's count-th distance plus the step between the two:
// the triangle inequality) are sorted in. Every point outside the cube is
// at least as far from the query as the cube's nearest face, so when the
// count-th distance found is below that, the answer is exact; when it is
// not (a stray point far from the rest), that query scans a cube wide
// enough for the count-th distance found, or twice as wide when fewer
// points were found, until it is. Distances are computed as FLANN's
// L2_Simple computes them (float, dx^2 + dy^2 + dz^2 in that order), so
// they equal a k-d tree's to the bit; which of several equally distant
// points is counted may differ, their distance does not.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <unordered_map>
#include <vector>

#include "cloud/pcl_cloud.h"

namespace ws {

class NeighbourGrid {
 public:
  // Cells of edge `cell` metres (> 0) over the cloud's bounding box; the
  // cloud must hold finite points only, and at least one.
  NeighbourGrid(const PclCloud& cloud, double cell);

  // The cloud's points over the cells that hold any.
  double PointsPerCell() const { return double(xyz_.size()) / double(cell_begin_.size() - 1); }

  // For every point of the cloud, fn(index, squared, found): the squared
  // distances to its `count` nearest points of the cloud, ascending, itself
  // first at 0; `found` is less than `count` only when the cloud holds fewer
  // points. Called on several threads, once per index.
  void ForEachPoint(int count, const std::function<void(int, const float*, int)>& fn) const;

 private:
  using Cell = std::array<int64_t, 3>;
  struct Range {
    int begin, end;  // positions in the sorted arrays
  };
  struct Block;

  Cell CellOf(const std::array<float, 3>& point) const;
  // Appends the points in the cube of cells within r of `cell` to the block.
  void Gather(const Cell& cell, int64_t r, Block* block) const;
  // Whether the `found` nearest points of that cube, squared[0 .. found),
  // are the cloud's `count` nearest to `query`: the count-th is nearer than
  // the cube's nearest face with a point beyond it.
  bool Exact(const std::array<float, 3>& query, const Cell& cell, int64_t r, int found, int count,
             const float* squared) const;
  // The count nearest of the block's points to `query`; how many were found.
  // `limit`: a guess at a squared distance the count nearest are within
  // (only a hint: exact whether it holds or not).
  static int Nearest(const std::array<float, 3>& query, Block* block, int count, float limit,
                     float* squared);
  // The same, for one query, scanning ever wider cubes until exact.
  int NearestAlone(const std::array<float, 3>& query, int64_t r, int count, float* squared) const;

  double cell_;
  std::array<double, 3> origin_;
  std::array<int64_t, 3> cells_;  // along x, y, z
  // The points sorted by column (cell x, cell y), then by cell z: a column's
  // cells within a z range are one run of consecutive points.
  std::vector<std::array<float, 3>> xyz_;
  std::vector<int> index_;  // in the cloud
  std::vector<Cell> cell_of_;
  std::vector<int> cell_begin_;  // where each occupied cell's run begins, then the end
  std::unordered_map<int64_t, Range> columns_;  // key: x * cells_[1] + y
};

}  // namespace ws
