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
#include "match/rectified_pair_writer.h"
#include "test_support.h"

namespace ws::test {
namespace {

// The row differences of the corners found in both images, ids paired as
// numbered or half-turned (id <-> count - 1 - id), whichever agrees better.
std::vector<double> RowDifferences(const BoardCorners& left, const BoardCorners& right, int count) {
  std::vector<double> best;
  double best_sum = INFINITY;
  for (const bool half_turned : {false, true}) {
    std::vector<double> rows;
    double sum = 0;
    for (size_t a = 0; a < left.ids.size(); ++a)
      for (size_t b = 0; b < right.ids.size(); ++b) {
        if (left.ids[a] != (half_turned ? count - 1 - right.ids[b] : right.ids[b])) continue;
        rows.push_back(left.points[a].y - right.points[b].y);
        sum += std::abs(rows.back());
      }
    if (!rows.empty() && sum / rows.size() < best_sum) best_sum = sum / rows.size(), best = rows;
  }
  return best;
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
  BoardRows result;
  result.pairs = int(ids.size());
  std::vector<double> rows;
  std::mutex mutex;
  cv::parallel_for_(cv::Range(0, int(ids.size())), [&](const cv::Range& range) {
    for (int i = range.start; i < range.end; ++i) {
      const cv::Mat left = cv::imread(RectifiedImagePath(out_dir, "left", ids[size_t(i)]), cv::IMREAD_GRAYSCALE);
      const cv::Mat right = cv::imread(RectifiedImagePath(out_dir, "right", ids[size_t(i)]), cv::IMREAD_GRAYSCALE);
      EXPECT_FALSE(left.empty() || right.empty()) << "pair " << ids[size_t(i)];
      if (left.empty() || right.empty()) continue;
      const BoardCorners l = detector->Detect(left), r = detector->Detect(right);
      if (l.empty() || r.empty()) continue;
      const std::vector<double> found = RowDifferences(l, r, board.corner_count());
      std::lock_guard<std::mutex> lock(mutex);
      ++result.boards;
      rows.insert(rows.end(), found.begin(), found.end());
    }
  });
  result.corners = int(rows.size());
  double squares = 0;
  for (double d : rows) squares += d * d;
  result.rms = std::sqrt(squares / std::max<size_t>(1, rows.size()));
  for (double& d : rows) d = std::abs(d);
  std::nth_element(rows.begin(), rows.begin() + rows.size() / 2, rows.end());
  result.median = rows.empty() ? 0 : rows[rows.size() / 2];
  return result;
}

void PrintBoardRows(const char* what, RectificationMode mode, const BoardRows& rows) {
  std::printf("[ rows ] %s, %-7s: boards found in %d of %d rectified pairs, %d corners, row error RMS %.3f px, "
              "median %.3f px\n",
              what, RectificationModeName(mode), rows.boards, rows.pairs, rows.corners, rows.rms, rows.median);
}

}  // namespace ws::test
