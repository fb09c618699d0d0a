// The grid's neighbour distances equal a brute-force search's to the bit,
// whatever the cell: the first cube of cells holds the answer, or the
// search widens until it does.
#include <gtest/gtest.h>

#include <algorithm>
#include <mutex>
#include <random>
#include <vector>

#include "cloud/neighbour_grid.h"
#include "cloud/pcl_cloud.h"

namespace {

ws::PclCloud Cloud(const std::vector<std::array<float, 3>>& points) {
  ws::PclCloud cloud;
  for (const auto& p : points) {
    pcl::PointXYZI point;
    point.x = p[0];
    point.y = p[1];
    point.z = p[2];
    point.intensity = 0;
    cloud.push_back(point);
  }
  return cloud;
}

// A noisy plane sampled every 2 cm, with points strayed far from it.
ws::PclCloud PlaneWithStrays() {
  std::mt19937 rng(5);
  std::normal_distribution<float> noise(0, 0.004f);
  std::uniform_real_distribution<float> box(-3, 3);
  std::vector<std::array<float, 3>> points;
  for (int row = 0; row < 60; ++row)
    for (int col = 0; col < 60; ++col)
      points.push_back({-0.6f + 0.02f * col, -0.6f + 0.02f * row, 2.0f + 0.3f * col * 0.02f + noise(rng)});
  for (int i = 0; i < 40; ++i) points.push_back({box(rng), box(rng), 3 + box(rng)});
  return Cloud(points);
}

// Every point's `count` nearest squared distances, by looking at all points,
// computed as the grid and FLANN compute them.
std::vector<std::vector<float>> BruteForce(const ws::PclCloud& cloud, int count) {
  std::vector<std::vector<float>> nearest;
  for (const auto& q : cloud) {
    std::vector<float> squared;
    for (const auto& p : cloud) {
      float d = 0;
      for (const float diff : {q.x - p.x, q.y - p.y, q.z - p.z}) d += diff * diff;
      squared.push_back(d);
    }
    std::sort(squared.begin(), squared.end());
    squared.resize(std::min(squared.size(), size_t(count)));
    nearest.push_back(squared);
  }
  return nearest;
}

std::vector<std::vector<float>> ByGrid(const ws::PclCloud& cloud, double cell, int count) {
  std::vector<std::vector<float>> nearest(cloud.size());
  std::vector<int> calls(cloud.size(), 0);
  std::mutex mutex;
  ws::NeighbourGrid(cloud, cell).ForEachPoint(count, [&](int index, const float* squared, int found) {
    std::lock_guard<std::mutex> lock(mutex);
    nearest[size_t(index)].assign(squared, squared + found);
    ++calls[size_t(index)];
  });
  EXPECT_EQ(std::count(calls.begin(), calls.end(), 1), long(cloud.size())) << "once per point";
  return nearest;
}

TEST(NeighbourGrid, FindsTheBruteForceDistancesAtEveryCell) {
  const ws::PclCloud cloud = PlaneWithStrays();
  for (const int count : {2, 9, 21}) {
    const auto expected = BruteForce(cloud, count);
    for (const double cell : {0.005, 0.03, 0.1, 10.0}) {  // far below the spacing to one cell
      const auto found = ByGrid(cloud, cell, count);
      int differing = 0;
      for (size_t i = 0; i < cloud.size(); ++i) differing += found[i] != expected[i];
      EXPECT_EQ(differing, 0) << "count " << count << ", cell " << cell;
    }
  }
}

TEST(NeighbourGrid, FindsWhatThereIsInACloudSmallerThanCount) {
  const ws::PclCloud cloud = Cloud({{0, 0, 1}, {0.1f, 0, 1}, {0, 0.3f, 1}});
  const auto found = ByGrid(cloud, 0.05, 5);
  EXPECT_EQ(found, BruteForce(cloud, 5));
  for (const auto& squared : found) EXPECT_EQ(squared.size(), 3u);
}

TEST(NeighbourGrid, CountsTheCellsItsPointsOccupy) {
  // Four points in two cells of 1 m, one in a third.
  const ws::PclCloud cloud =
      Cloud({{0.1f, 0.1f, 0.1f}, {0.2f, 0.1f, 0.1f}, {1.5f, 0.1f, 0.1f}, {1.6f, 0.2f, 0.1f}, {3.5f, 3.5f, 3.5f}});
  EXPECT_DOUBLE_EQ(ws::NeighbourGrid(cloud, 1.0).PointsPerCell(), 5.0 / 3);
}

TEST(NeighbourGrid, RefusesAnEmptyCloudAndACellNotAboveZero) {
  EXPECT_THROW(ws::NeighbourGrid(ws::PclCloud(), 0.1), std::invalid_argument);
  EXPECT_THROW(ws::NeighbourGrid(Cloud({{0, 0, 1}}), 0), std::invalid_argument);
}

}  // namespace
