#include "rectified_board_rows.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "detect/corner_detector.h"
#include "match/frame_image_writer.h"
#include "test_support.h"

namespace ws::test {
namespace {

struct CornerPair {
  cv::Point2f left, right;
};

// The corners found in both images, ids paired as numbered or half-turned
// (id <-> count - 1 - id), whichever puts them on closer rows.
std::vector<CornerPair> PairCorners(const BoardCorners& left, const BoardCorners& right, int count) {
  std::vector<CornerPair> best;
  double best_mean = INFINITY;
  for (const bool half_turned : {false, true}) {
    std::vector<CornerPair> pairs;
    double sum = 0;
    for (size_t a = 0; a < left.ids.size(); ++a)
      for (size_t b = 0; b < right.ids.size(); ++b) {
        if (left.ids[a] != (half_turned ? count - 1 - right.ids[b] : right.ids[b])) continue;
        pairs.push_back({left.points[a], right.points[b]});
        sum += std::abs(left.points[a].y - right.points[b].y);
      }
    if (!pairs.empty() && sum / pairs.size() < best_mean) best_mean = sum / pairs.size(), best = pairs;
  }
  return best;
}

// The angle of a rectified pixel's ray from the epipolar planes' normal.
double Psi(const Rectification& rect, const cv::Point2f& pixel) {
  const cv::Vec3d ray = RectifiedRay(rect, pixel.x, pixel.y);
  return std::asin(ray[0] / cv::norm(ray));
}

double Rms(const std::vector<double>& values) {
  double squares = 0;
  for (double d : values) squares += d * d;
  return std::sqrt(squares / std::max<size_t>(1, values.size()));
}

}  // namespace

BoardRows MeasureRectifiedBoardRows(const std::string& images, const std::string& calib,
                                    RectificationMode mode, const std::string& out_dir,
                                    const BoardSpec& board) {
  const auto r = RunCommand({"stereo-match", "--log-dir", out_dir, "--calib", calib, "--rectification",
                             RectificationModeName(mode), "--num-disparities", "16", "--cloud-step", "8",
                             "--save-rectified", out_dir, "--in-url", "file://" + images + "?speed=0",
                             "--out-url", "file://" + out_dir + "/match.lcmlog?mode=w"},
                            300);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  std::vector<int64_t> ids;
  for (const auto& entry : std::filesystem::directory_iterator(out_dir)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("left_", 0) == 0 && entry.path().extension() == ".png")
      ids.push_back(std::stoll(name.substr(5, name.size() - 9)));
  }
  std::sort(ids.begin(), ids.end());
  const auto detector = MakeCornerDetector(board);
  const Rectification rect = BuildRectification(StereoRigFromFile(calib), RectifyOptions{1.0, {}, mode});
  BoardRows result;
  result.pairs = int(ids.size());
  std::vector<double> rows, central;
  std::vector<cv::Vec2d> per_pair(ids.size(), cv::Vec2d(NAN, NAN));
  std::mutex mutex;
  cv::parallel_for_(cv::Range(0, int(ids.size())), [&](const cv::Range& range) {
    for (int i = range.start; i < range.end; ++i) {
      const cv::Mat left = cv::imread(FrameImagePath(out_dir, "left", ids[size_t(i)]), cv::IMREAD_GRAYSCALE);
      const cv::Mat right = cv::imread(FrameImagePath(out_dir, "right", ids[size_t(i)]), cv::IMREAD_GRAYSCALE);
      EXPECT_FALSE(left.empty() || right.empty()) << "pair " << ids[size_t(i)];
      if (left.empty() || right.empty()) continue;
      const BoardCorners l = detector->Detect(left), r = detector->Detect(right);
      if (l.empty() || r.empty()) continue;
      const std::vector<CornerPair> pairs = PairCorners(l, r, board.corner_count());
      std::lock_guard<std::mutex> lock(mutex);
      ++result.boards;
      double sum = 0, squares = 0;
      for (const CornerPair& p : pairs) {
        rows.push_back(p.left.y - p.right.y);
        sum += rows.back();
        squares += rows.back() * rows.back();
        if (std::max(std::abs(Psi(rect, p.left)), std::abs(Psi(rect, p.right))) <= M_PI / 3)
          central.push_back(rows.back());
      }
      const double mean = sum / double(pairs.size());
      per_pair[size_t(i)] = cv::Vec2d(mean, std::sqrt(std::max(0.0, squares / double(pairs.size()) - mean * mean)));
    }
  });
  std::vector<double> scatters;
  for (size_t i = 0; i < per_pair.size(); ++i) {
    if (std::isnan(per_pair[i][0])) continue;
    scatters.push_back(per_pair[i][1]);
    if (std::abs(per_pair[i][0]) > std::abs(result.largest_shift)) result.largest_shift = per_pair[i][0];
    if (per_pair[i][1] > result.largest_scatter) result.largest_scatter = per_pair[i][1], result.largest_scatter_pair = ids[i];
  }
  std::sort(scatters.begin(), scatters.end());
  result.pair_scatter_median = scatters.empty() ? 0 : scatters[scatters.size() / 2];
  result.corners = int(rows.size());
  result.rms = Rms(rows);
  result.central_corners = int(central.size());
  result.central_rms = Rms(central);
  for (double& d : rows) d = std::abs(d);
  std::nth_element(rows.begin(), rows.begin() + rows.size() / 2, rows.end());
  result.median = rows.empty() ? 0 : rows[rows.size() / 2];
  return result;
}

void PrintBoardRows(const char* what, RectificationMode mode, const BoardRows& rows) {
  std::printf("[ rows ] %s, %-7s: boards found in %d of %d rectified pairs, %d corners, row error RMS %.3f px, "
              "median %.3f px; within 60 degrees of the normal: %d corners, RMS %.3f px\n",
              what, RectificationModeName(mode), rows.boards, rows.pairs, rows.corners, rows.rms, rows.median,
              rows.central_corners, rows.central_rms);
  std::printf("[ rows ]   per pair: scatter about the pair's own mean row difference median %.3f px, largest "
              "%.3f px (pair %lld); largest mean row difference %+.3f px\n",
              rows.pair_scatter_median, rows.largest_scatter, static_cast<long long>(rows.largest_scatter_pair),
              rows.largest_shift);
}

}  // namespace ws::test
