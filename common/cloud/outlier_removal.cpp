#include "cloud/outlier_removal.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <flann/flann.hpp>
#include <opencv2/core.hpp>

namespace ws {
namespace {

// Points searched per FLANN call: big enough that the call's own cost
// vanishes, small enough to keep the result arrays in cache.
constexpr int kChunk = 4096;

}  // namespace

pcl::Indices StatisticalInliers(const PclCloud::Ptr& cloud, int mean_k, double stddev_mul) {
  const int n = int(cloud->size());
  std::vector<float> xyz(size_t(n) * 3);
  for (int i = 0; i < n; ++i) {
    const pcl::PointXYZI& p = (*cloud)[size_t(i)];
    std::copy_n(&p.x, 3, &xyz[size_t(i) * 3]);
  }
  // The tree and the search pcl::KdTreeFLANN makes: 15 points per leaf, exact
  // search (checks unlimited, eps 0), results sorted by distance.
  const flann::Matrix<float> points(xyz.data(), size_t(n), 3);
  flann::Index<flann::L2_Simple<float>> index(points, flann::KDTreeSingleIndexParams(15));
  index.buildIndex();
  const flann::SearchParams search(-1, 0.0f);
  const int searched = mean_k + 1;  // the point itself comes back too

  std::vector<float> distances(size_t(n), 0.f);
  std::vector<uint8_t> valid(size_t(n), 0);
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
        const float* row = dists[size_t(q)];
        if (indices[size_t(q)][0] < 0) continue;  // nothing found
        double sum = 0;
        for (int k = 1; k < searched; ++k) sum += std::sqrt(row[k]);
        distances[size_t(first + q)] = float(sum / mean_k);
        valid[size_t(first + q)] = 1;
      }
    }
  });
  // PCL's statistics, term for term (statistical_outlier_removal.hpp).
  double sum = 0, sum_squares = 0;
  int valid_count = 0;
  for (int i = 0; i < n; ++i) {
    sum += distances[size_t(i)];
    sum_squares += distances[size_t(i)] * distances[size_t(i)];
    valid_count += valid[size_t(i)];
  }
  const double mean = sum / double(valid_count);
  const double variance =
      (sum_squares - sum * sum / double(valid_count)) / (double(valid_count) - 1);
  const double threshold = mean + stddev_mul * std::sqrt(variance);
  pcl::Indices kept;
  kept.reserve(size_t(n));
  for (int i = 0; i < n; ++i)
    if (!(distances[size_t(i)] > threshold)) kept.push_back(i);
  return kept;
}

}  // namespace ws
