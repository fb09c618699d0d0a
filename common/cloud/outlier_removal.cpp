#include "cloud/outlier_removal.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <flann/flann.hpp>
#include <opencv2/core.hpp>

#include "cloud/neighbour_grid.h"

namespace ws {
namespace {

// Points searched per FLANN call: big enough that the call's own cost
// vanishes, small enough to keep the result arrays in cache.
constexpr int kChunk = 4096;

// Each point's mean distance to its mean_k neighbours, from the squared
// distances of its mean_k + 1 nearest points, ascending (itself first), as
// PCL sums them: float square roots added in a double.
float MeanDistance(const float* squared, int mean_k) {
  double sum = 0;
  for (int k = 1; k <= mean_k; ++k) sum += std::sqrt(squared[k]);
  return float(sum / mean_k);
}

struct MeanDistances {
  std::vector<float> distance;
  std::vector<uint8_t> valid;  // 0: no neighbours found, the point is not in the statistic
};

MeanDistances KdTreeMeanDistances(const PclCloud& cloud, int mean_k) {
  const int n = int(cloud.size());
  std::vector<float> xyz(size_t(n) * 3);
  for (int i = 0; i < n; ++i) std::copy_n(&cloud[size_t(i)].x, 3, &xyz[size_t(i) * 3]);
  // The tree and the search pcl::KdTreeFLANN makes: 15 points per leaf, exact
  // search (checks unlimited, eps 0), results sorted by distance.
  const flann::Matrix<float> points(xyz.data(), size_t(n), 3);
  flann::Index<flann::L2_Simple<float>> index(points, flann::KDTreeSingleIndexParams(15));
  index.buildIndex();
  const flann::SearchParams search(-1, 0.0f);
  const int searched = mean_k + 1;  // the point itself comes back too

  MeanDistances means{std::vector<float>(size_t(n), 0.f), std::vector<uint8_t>(size_t(n), 0)};
  cv::parallel_for_(cv::Range(0, (n + kChunk - 1) / kChunk), [&](const cv::Range& chunks) {
    std::vector<int> neighbours(size_t(kChunk) * searched);
    std::vector<float> squared(size_t(kChunk) * searched);
    for (int chunk = chunks.start; chunk < chunks.end; ++chunk) {
      const int first = chunk * kChunk, count = std::min(kChunk, n - first);
      flann::Matrix<int> indices(neighbours.data(), size_t(count), size_t(searched));
      flann::Matrix<float> dists(squared.data(), size_t(count), size_t(searched));
      index.knnSearch(flann::Matrix<float>(&xyz[size_t(first) * 3], size_t(count), 3), indices, dists,
                      size_t(searched), search);
      for (int q = 0; q < count; ++q) {
        if (indices[size_t(q)][0] < 0) continue;  // nothing found
        means.distance[size_t(first + q)] = MeanDistance(dists[size_t(q)], mean_k);
        means.valid[size_t(first + q)] = 1;
      }
    }
  });
  return means;
}

// A point's mean_k + 1 nearest lie in the first cube of 3^3 cells about its
// own when their radius is below the cell's edge. On a surface holding m
// points per occupied cell that radius is sqrt((mean_k + 1) / (pi m))
// cells: at m = kReach^2 (mean_k + 1) / pi it is 1 / kReach of a cell, and
// the first cube nearly always holds the answer. A larger m costs more
// points per query; a smaller one more queries past the first cube.
constexpr double kReach = 1.5;
// Grids built at most, the cell grown each time the points per cell fall
// short of half of what is wanted.
constexpr int kMaxGrids = 3;

// The grid starts at the cell that gives that m on a surface sampled once
// per leaf^2 (VoxelGrid's output where the points are denser than the
// leaf); where they are sparser (one point a voxel: a leaf finer than their
// spacing), it grows the cell by sqrt(wanted / measured), as a surface's
// points per cell grow as the square of the cell.
NeighbourGrid GridFor(const PclCloud& cloud, int mean_k, double voxel_leaf) {
  const double wanted = kReach * kReach * (mean_k + 1) / M_PI;
  double cell = voxel_leaf * std::sqrt(wanted);
  for (int grids = 1;; ++grids) {
    NeighbourGrid grid(cloud, cell);
    if (grid.PointsPerCell() >= wanted / 2 || grids == kMaxGrids) return grid;
    cell *= std::sqrt(wanted / grid.PointsPerCell());
  }
}

MeanDistances GridMeanDistances(const PclCloud& cloud, int mean_k, double voxel_leaf) {
  MeanDistances means{std::vector<float>(cloud.size(), 0.f), std::vector<uint8_t>(cloud.size(), 0)};
  GridFor(cloud, mean_k, voxel_leaf)
      .ForEachPoint(mean_k + 1, [&](int index, const float* squared, int found) {
        if (found < mean_k + 1) return;
        means.distance[size_t(index)] = MeanDistance(squared, mean_k);
        means.valid[size_t(index)] = 1;
      });
  return means;
}

}  // namespace

pcl::Indices StatisticalInliers(const PclCloud::Ptr& cloud, int mean_k, double stddev_mul,
                                double voxel_leaf) {
  const MeanDistances means = voxel_leaf > 0 ? GridMeanDistances(*cloud, mean_k, voxel_leaf)
                                             : KdTreeMeanDistances(*cloud, mean_k);
  const int n = int(cloud->size());
  // PCL's statistics, term for term (statistical_outlier_removal.hpp).
  double sum = 0, sum_squares = 0;
  int valid_count = 0;
  for (int i = 0; i < n; ++i) {
    sum += means.distance[size_t(i)];
    sum_squares += means.distance[size_t(i)] * means.distance[size_t(i)];
    valid_count += means.valid[size_t(i)];
  }
  const double mean = sum / double(valid_count);
  const double variance =
      (sum_squares - sum * sum / double(valid_count)) / (double(valid_count) - 1);
  const double threshold = mean + stddev_mul * std::sqrt(variance);
  pcl::Indices kept;
  kept.reserve(size_t(n));
  for (int i = 0; i < n; ++i)
    if (!(means.distance[size_t(i)] > threshold)) kept.push_back(i);
  return kept;
}

}  // namespace ws
