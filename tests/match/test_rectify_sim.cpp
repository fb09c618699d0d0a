// Rectification quality on the simulator's board pairs (issue #6): with the
// rig's own B-spline model, corresponding corners land on the same rectified
// row across the whole field, for the true corners and for the corners the
// detector finds in the rendered images; with the rig refitted as poly6 they
// do not.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <mutex>
#include <vector>

#include <opencv2/core.hpp>

#include "detect/corner_detector.h"
#include "match_fixtures.h"
#include "rectify/rectification.h"
#include "sim/simulator.h"

namespace {

using namespace ws::test;

// Row differences of corresponding points, binned over a grid of regions of
// the left rectified image.
class RowErrors {
 public:
  static constexpr int kCols = 4, kRows = 3;

  explicit RowErrors(cv::Size size) : size_(size) {}

  void Add(const cv::Point2d& left, const cv::Point2d& right) {
    const int col = std::clamp(int(left.x * kCols / size_.width), 0, kCols - 1);
    const int row = std::clamp(int(left.y * kRows / size_.height), 0, kRows - 1);
    Region& region = regions_[row * kCols + col];
    const double d = left.y - right.y;
    ++region.n;
    region.sum += d;
    region.sum_squares += d * d;
    worst_ = std::max(worst_, std::abs(d));
    sum_squares_ += d * d;
    ++n_;
  }

  int count() const { return n_; }
  double rms() const { return std::sqrt(sum_squares_ / std::max(1, n_)); }
  double worst() const { return worst_; }
  int empty_regions() const {
    return int(std::count_if(regions_, regions_ + kCols * kRows, [](const Region& r) { return r.n == 0; }));
  }
  // The largest |mean row difference| of a region: a systematic error.
  double worst_region_mean() const {
    double worst = 0;
    for (const Region& r : regions_)
      if (r.n) worst = std::max(worst, std::abs(r.sum / r.n));
    return worst;
  }
  void Print(const char* what) const {
    std::printf("[ rectify ] %s: %d pairs, row error RMS %.3g px, max %.3g px, worst region mean %.3g px\n",
                what, n_, rms(), worst_, worst_region_mean());
    for (int row = 0; row < kRows; ++row) {
      std::printf("[ rectify ]   ");
      for (int col = 0; col < kCols; ++col) {
        const Region& r = regions_[row * kCols + col];
        std::printf(" %4d: %+.4f/%.4f", r.n, r.n ? r.sum / r.n : 0.0,
                    r.n ? std::sqrt(r.sum_squares / r.n) : 0.0);
      }
      std::printf("   (n: mean/RMS px)\n");
    }
  }

 private:
  struct Region {
    int n = 0;
    double sum = 0, sum_squares = 0;
  };
  cv::Size size_;
  Region regions_[kCols * kRows];
  double worst_ = 0, sum_squares_ = 0;
  int n_ = 0;
};

class RectificationQuality : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    simulator_ = new ws::Simulator(ws::LoadSimConfig("config/sim/default.yaml"));
    truth_ = new ws::SimTruth(simulator_->Truth());
  }
  static void TearDownTestSuite() {
    delete truth_;
    delete simulator_;
  }

  // Rectifies the true corners of every board frame that both cameras see.
  static RowErrors TrueCornerRows(const ws::StereoRig& rig) {
    const ws::Rectification rect = ws::BuildRectification(rig);
    RowErrors rows(rect.size);
    for (const ws::SimFrameTruth& frame : truth_->frames) {
      if (frame.kind != "board") continue;
      for (size_t id = 0; id < frame.left.corners.size(); ++id) {
        if (!frame.left.in_image[id] || !frame.right.in_image[id]) continue;
        cv::Point2d l, r;
        EXPECT_TRUE(ws::RectifyPoint(rect, rig, true, frame.left.corners[id], &l));
        EXPECT_TRUE(ws::RectifyPoint(rect, rig, false, frame.right.corners[id], &r));
        rows.Add(l, r);
      }
    }
    return rows;
  }

  static ws::Simulator* simulator_;
  static ws::SimTruth* truth_;
};

ws::Simulator* RectificationQuality::simulator_ = nullptr;
ws::SimTruth* RectificationQuality::truth_ = nullptr;

TEST_F(RectificationQuality, TrueCornersShareARowAcrossTheWholeField) {
  const ws::StereoRig rig = RigFromTruth(*truth_);
  const RowErrors bspline = TrueCornerRows(rig);
  bspline.Print("true corners, bspline (the rig's own model)");
  EXPECT_GT(bspline.count(), 1000);
  EXPECT_EQ(bspline.empty_regions(), 0) << "corners in every part of the rectified image";
  EXPECT_LT(bspline.worst(), 0.1);

  // The same rig described by poly6, the best least-squares fit to the lens:
  // its rows disagree where the fit misses the mustache.
  const RowErrors poly6 = TrueCornerRows(RigFittedAs(rig, "poly6"));
  poly6.Print("true corners, poly6 fit of the same lens");
  EXPECT_GT(poly6.worst(), 10 * std::max(bspline.worst(), 0.01));
}

TEST_F(RectificationQuality, DetectedCornersShareARowAcrossTheWholeField) {
  const ws::StereoRig rig = RigFromTruth(*truth_);
  const ws::Rectification rect = ws::BuildRectification(rig);
  const auto detector = ws::MakeCornerDetector(simulator_->config().board->board);
  std::vector<int> frames;
  for (const ws::SimFrameTruth& frame : truth_->frames)
    if (frame.kind == "board" && frame.left.view == ws::BoardView::full &&
        frame.right.view == ws::BoardView::full)
      frames.push_back(frame.index);
  ASSERT_GE(frames.size(), 15u);

  RowErrors rows(rect.size);
  std::mutex mutex;
  int boards = 0;
  cv::parallel_for_(cv::Range(0, int(frames.size())), [&](const cv::Range& range) {
    for (int i = range.start; i < range.end; ++i) {
      const auto [left, right] = simulator_->Render(frames[size_t(i)]);
      const ws::BoardCorners l = detector->Detect(left), r = detector->Detect(right);
      std::lock_guard<std::mutex> lock(mutex);
      boards += !l.empty() && !r.empty();
      for (size_t a = 0; a < l.ids.size(); ++a)
        for (size_t b = 0; b < r.ids.size(); ++b) {
          if (l.ids[a] != r.ids[b]) continue;
          cv::Point2d lr, rr;
          ASSERT_TRUE(ws::RectifyPoint(rect, rig, true, l.points[a], &lr));
          ASSERT_TRUE(ws::RectifyPoint(rect, rig, false, r.points[b], &rr));
          rows.Add(lr, rr);
        }
    }
  });
  rows.Print("detected corners, bspline");
  EXPECT_EQ(boards, int(frames.size()));
  EXPECT_EQ(rows.empty_regions(), 0);
  // Each corner is found within 0.043 px RMS (stereo-detect's measured
  // accuracy), so a row difference scatters by about 0.06 px RMS: no part of
  // the field may be off on average, nor scattered by more than 0.1 px.
  EXPECT_LT(rows.rms(), 0.1);
  EXPECT_LT(rows.worst_region_mean(), 0.05);
}

}  // namespace
