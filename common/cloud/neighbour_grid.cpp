#include "cloud/neighbour_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

#include <opencv2/core.hpp>
#include <pcl/common/common.h>

namespace ws {
namespace {

// Keeps squared[0 .. *found) the `count` smallest distances seen, ascending.
void Insert(float distance, int count, float* squared, int* found) {
  if (*found == count && !(distance < squared[count - 1])) return;
  int i = *found < count ? (*found)++ : count - 1;
  for (; i > 0 && squared[i - 1] > distance; --i) squared[i] = squared[i - 1];
  squared[i] = distance;
}

size_t CountWithin(const float* distance, size_t n, float limit) {
  size_t within = 0;
  for (size_t j = 0; j < n; ++j) within += distance[j] <= limit;
  return within;
}

// Tries at a narrower limit before the sort.
constexpr int kNarrowings = 3;

// Points a parallel task takes on: enough that the task's cost vanishes.
constexpr double kPointsPerTask = 4096;

constexpr float kNoLimit = std::numeric_limits<float>::infinity();

// FLANN's L2_Simple<float>: the sum in float, term by term from x.
float SquaredDistance(const std::array<float, 3>& a, const std::array<float, 3>& b) {
  float result = 0;
  for (size_t i = 0; i < 3; ++i) {
    const float diff = a[i] - b[i];
    result += diff * diff;
  }
  return result;
}

// A point outside the searched cube whose float distance were computed a few
// ulps below its true distance must still not beat the count-th found: the
// cube's face distance must exceed the count-th distance by more than that.
constexpr double kRoundingMargin = 1e-5;

}  // namespace

// The points of a cube of cells, one flat array per coordinate.
struct NeighbourGrid::Block {
  std::vector<float> x, y, z;
  std::vector<float> squared, near;  // scratch: distances to the query, those within a limit

  void Clear() {
    x.clear();
    y.clear();
    z.clear();
  }
};

NeighbourGrid::NeighbourGrid(const PclCloud& cloud, double cell) : cell_(cell) {
  if (!(cell > 0)) throw std::invalid_argument("NeighbourGrid: the cell must be > 0");
  if (cloud.empty()) throw std::invalid_argument("NeighbourGrid: the cloud is empty");
  pcl::PointXYZI min, max;
  pcl::getMinMax3D(cloud, min, max);
  origin_ = {min.x, min.y, min.z};
  const std::array<double, 3> extent = {double(max.x) - min.x, double(max.y) - min.y,
                                        double(max.z) - min.z};
  for (size_t a = 0; a < 3; ++a) {
    const double cells = std::floor(extent[a] / cell_) + 1;
    // Below 2^31 a column's key, x * cells_[1] + y, fits an int64_t.
    if (!(cells < double(int64_t(1) << 31)))
      throw std::invalid_argument("NeighbourGrid: the cloud spans too many cells");
    cells_[a] = int64_t(cells);
  }
  std::vector<Cell> cell_of(cloud.size());
  for (size_t i = 0; i < cloud.size(); ++i) cell_of[i] = CellOf({cloud[i].x, cloud[i].y, cloud[i].z});
  index_.resize(cloud.size());
  std::iota(index_.begin(), index_.end(), 0);
  std::sort(index_.begin(), index_.end(),
            [&](int a, int b) { return cell_of[size_t(a)] < cell_of[size_t(b)]; });
  xyz_.reserve(index_.size());
  cell_of_.reserve(index_.size());
  columns_.reserve(index_.size());
  for (size_t position = 0; position < index_.size(); ++position) {
    const Cell& c = cell_of[size_t(index_[position])];
    const pcl::PointXYZI& p = cloud[size_t(index_[position])];
    if (position == 0 || c != cell_of_.back()) cell_begin_.push_back(int(position));
    xyz_.push_back({p.x, p.y, p.z});
    cell_of_.push_back(c);
    Range& column = columns_.try_emplace(c[0] * cells_[1] + c[1], Range{int(position), 0}).first->second;
    column.end = int(position) + 1;
  }
  cell_begin_.push_back(int(index_.size()));
}

NeighbourGrid::Cell NeighbourGrid::CellOf(const std::array<float, 3>& point) const {
  Cell cell;
  for (size_t a = 0; a < 3; ++a)
    cell[a] = std::clamp(int64_t(std::floor((point[a] - origin_[a]) / cell_)), int64_t(0), cells_[a] - 1);
  return cell;
}

void NeighbourGrid::Gather(const Cell& cell, int64_t r, Block* block) const {
  for (int64_t x = std::max<int64_t>(cell[0] - r, 0); x <= std::min(cell[0] + r, cells_[0] - 1); ++x)
    for (int64_t y = std::max<int64_t>(cell[1] - r, 0); y <= std::min(cell[1] + r, cells_[1] - 1); ++y) {
      const auto column = columns_.find(x * cells_[1] + y);
      if (column == columns_.end()) continue;
      const auto begin = cell_of_.begin() + column->second.begin;
      const auto end = cell_of_.begin() + column->second.end;
      auto first = std::lower_bound(begin, end, cell[2] - r,
                                    [](const Cell& c, int64_t z) { return c[2] < z; });
      for (; first != end && (*first)[2] <= cell[2] + r; ++first) {
        const std::array<float, 3>& p = xyz_[size_t(first - cell_of_.begin())];
        block->x.push_back(p[0]);
        block->y.push_back(p[1]);
        block->z.push_back(p[2]);
      }
    }
}

bool NeighbourGrid::Exact(const std::array<float, 3>& query, const Cell& cell, int64_t r, int found,
                          int count, const float* squared) const {
  // The nearest face of the cube with a point beyond it.
  double face = std::numeric_limits<double>::infinity();
  for (size_t a = 0; a < 3; ++a) {
    if (cell[a] - r > 0) face = std::min(face, query[a] - (origin_[a] + double(cell[a] - r) * cell_));
    if (cell[a] + r < cells_[a] - 1)
      face = std::min(face, origin_[a] + double(cell[a] + r + 1) * cell_ - query[a]);
  }
  return std::isinf(face) ||  // the cube holds the whole cloud
         (found == count && double(squared[count - 1]) < face * face * (1 - kRoundingMargin));
}

int NeighbourGrid::Nearest(const std::array<float, 3>& query, Block* block, int count, float limit,
                           float* squared) {
  // FLANN's L2_Simple<float>: the sum in float, term by term from x. A loop
  // with no branch, for the compiler to vectorise.
  const size_t n = block->x.size();
  block->squared.resize(n);
  float* distance = block->squared.data();
  for (size_t j = 0; j < n; ++j) {
    const float dx = query[0] - block->x[j], dy = query[1] - block->y[j], dz = query[2] - block->z[j];
    float d = 0;
    d += dx * dx;
    d += dy * dy;
    d += dz * dz;
    distance[j] = d;
  }
  // When `count` of them are within `limit`, so are the count nearest. On a
  // surface (a voxelised depth cloud) the points within a squared radius
  // grow as it does, so 2 count / near of the squared limit holds about
  // twice count of them: a narrower limit, kept when it holds at least
  // count (a multiply: the volume's law, a cube root and a power, was a
  // seventh of the search's time in libm). Counting is a loop the compiler vectorises; only
  // the few within the limit are sorted in.
  size_t near = CountWithin(distance, n, limit);
  if (near < size_t(count)) {
    limit = *std::max_element(distance, distance + n);
    near = n;
  }
  for (int narrowing = 0; narrowing < kNarrowings && near > size_t(2 * count); ++narrowing) {
    const float narrower = limit * (2.0f * float(count) / float(near));
    const size_t within = CountWithin(distance, n, narrower);
    if (within < size_t(count)) break;
    limit = narrower;
    near = within;
  }
  block->near.resize(n);
  near = 0;
  for (size_t j = 0; j < n; ++j) {
    block->near[near] = distance[j];
    near += distance[j] <= limit;
  }
  const float* candidates = block->near.data();
  int found = 0;
  for (size_t j = 0; j < near; ++j) Insert(candidates[j], count, squared, &found);
  return found;
}

int NeighbourGrid::NearestAlone(const std::array<float, 3>& query, int64_t r, int count,
                                float* squared) const {
  const Cell cell = CellOf(query);
  Block block;
  for (;;) {
    block.Clear();
    Gather(cell, r, &block);
    const int found = Nearest(query, &block, count, kNoLimit, squared);
    if (Exact(query, cell, r, found, count, squared)) return found;
    // The cube whose faces are all beyond the count-th distance found.
    r = found == count ? std::max(r + 1, int64_t(std::sqrt(double(squared[count - 1])) / cell_) + 2)
                       : 2 * r;
  }
}

void NeighbourGrid::ForEachPoint(int count, const std::function<void(int, const float*, int)>& fn) const {
  const int cells = int(cell_begin_.size()) - 1;
  // parallel_for_ would otherwise make a task of every cell.
  const double stripes = std::ceil(double(xyz_.size()) / kPointsPerTask);
  cv::parallel_for_(cv::Range(0, cells), [&](const cv::Range& range) {
    Block block;
    std::vector<float> squared(static_cast<size_t>(count));
    const std::array<float, 3>* previous = nullptr;
    float previous_reach = 0;  // its count-th squared distance
    for (int c = range.start; c < range.end; ++c) {
      const Cell& cell = cell_of_[size_t(cell_begin_[size_t(c)])];
      block.Clear();
      Gather(cell, 1, &block);
      for (int position = cell_begin_[size_t(c)]; position < cell_begin_[size_t(c) + 1]; ++position) {
        const std::array<float, 3>& query = xyz_[size_t(position)];
        // The previous query's count nearest are within its count-th
        // distance plus the step between the two of this one (the triangle
        // inequality): most of the block is farther.
        float limit = kNoLimit;
        if (previous) {
          const float reach = std::sqrt(previous_reach) + std::sqrt(SquaredDistance(query, *previous));
          limit = reach * reach;
        }
        int found = Nearest(query, &block, count, limit, squared.data());
        if (!Exact(query, cell, 1, found, count, squared.data()))
          found = NearestAlone(query, 2, count, squared.data());
        fn(index_[size_t(position)], squared.data(), found);
        previous = found == count ? &query : nullptr;
        previous_reach = squared[size_t(count) - 1];
      }
    }
  }, stripes);
}

}  // namespace ws
