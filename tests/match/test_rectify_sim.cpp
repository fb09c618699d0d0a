// Rectification quality on the simulator's board pairs (issue #6): with the
// rig's own B-spline model, corresponding corners land on the same rectified
// row across the whole field, for the true corners and for the corners the
// detector finds in the rendered images; with the rig refitted as poly6 they
// do not.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <mutex>
#include <utility>
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

// Rectifies the true corners of every board frame that both cameras see
// (those with no rectified pixel, a pinhole's rays behind it, are counted in
// *unrepresentable).
RowErrors RowsOfTrueCorners(const ws::SimTruth& truth, const ws::Rig& rig,
                         const ws::RectifyOptions& options, int* unrepresentable = nullptr) {
  const ws::Rectification rect = ws::BuildRectification(rig, options);
  RowErrors rows(rect.size);
  for (const ws::SimFrameTruth& frame : truth.frames) {
    if (frame.kind != "board") continue;
    for (size_t id = 0; id < frame.left.corners.size(); ++id) {
      if (!frame.left.in_image[id] || !frame.right.in_image[id]) continue;
      cv::Point2d l, r;
      const bool both = ws::RectifyPoint(rect, rig, true, frame.left.corners[id], &l) &&
                        ws::RectifyPoint(rect, rig, false, frame.right.corners[id], &r);
      if (unrepresentable) *unrepresentable += !both;
      else EXPECT_TRUE(both);
      if (both) rows.Add(l, r);
    }
  }
  return rows;
}

// The corners the detector finds in every rendered board frame that both
// cameras see whole, each pair rectified (left, right); *frames: how many
// such frames, *boards: in how many both boards were found.
std::vector<std::pair<cv::Point2d, cv::Point2d>> DetectedCornerPairs(
    const ws::Simulator& simulator, const ws::SimTruth& truth, const ws::Rig& rig,
    const ws::Rectification& rect, int* frames, int* boards) {
  const auto detector = ws::MakeCornerDetector(simulator.config().board->board);
  std::vector<int> whole;
  for (const ws::SimFrameTruth& frame : truth.frames)
    if (frame.kind == "board" && frame.left.view == ws::BoardView::full &&
        frame.right.view == ws::BoardView::full)
      whole.push_back(frame.index);
  *frames = int(whole.size());
  *boards = 0;
  std::vector<std::pair<cv::Point2d, cv::Point2d>> pairs;
  std::mutex mutex;
  cv::parallel_for_(cv::Range(0, int(whole.size())), [&](const cv::Range& range) {
    for (int i = range.start; i < range.end; ++i) {
      const auto [left, right] = simulator.Render(whole[size_t(i)]);
      const ws::BoardCorners l = detector->Detect(left), r = detector->Detect(right);
      std::lock_guard<std::mutex> lock(mutex);
      *boards += !l.empty() && !r.empty();
      for (size_t a = 0; a < l.ids.size(); ++a)
        for (size_t b = 0; b < r.ids.size(); ++b) {
          if (l.ids[a] != r.ids[b]) continue;
          cv::Point2d lr, rr;
          EXPECT_TRUE(ws::RectifyPoint(rect, rig, true, l.points[a], &lr));
          EXPECT_TRUE(ws::RectifyPoint(rect, rig, false, r.points[b], &rr));
          pairs.emplace_back(lr, rr);
        }
    }
  });
  return pairs;
}

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

  static RowErrors TrueCornerRows(const ws::Rig& rig) {
    return RowsOfTrueCorners(*truth_, rig, ws::RectifyOptions());
  }

  static ws::Simulator* simulator_;
  static ws::SimTruth* truth_;
};

ws::Simulator* RectificationQuality::simulator_ = nullptr;
ws::SimTruth* RectificationQuality::truth_ = nullptr;

TEST_F(RectificationQuality, TrueCornersShareARowAcrossTheWholeField) {
  const ws::Rig rig = truth_->rig;
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
  const ws::Rig rig = truth_->rig;
  const ws::Rectification rect = ws::BuildRectification(rig);
  int frames = 0, boards = 0;
  const auto pairs = DetectedCornerPairs(*simulator_, *truth_, rig, rect, &frames, &boards);
  ASSERT_GE(frames, 15);
  RowErrors rows(rect.size);
  for (const auto& [l, r] : pairs) rows.Add(l, r);
  rows.Print("detected corners, bspline");
  EXPECT_EQ(boards, frames);
  EXPECT_EQ(rows.empty_regions(), 0);
  // Each corner is found within 0.043 px RMS (stereo-detect's measured
  // accuracy), so a row difference scatters by about 0.06 px RMS: no part of
  // the field may be off on average, nor scattered by more than 0.1 px.
  EXPECT_LT(rows.rms(), 0.1);
  EXPECT_LT(rows.worst_region_mean(), 0.05);
}

// Lat-lon rectification (rectification.h) of the simulator's 200-degree
// fisheye rig (config/sim/fisheye.yaml): every true corner pair, those past
// 90 degrees off axis included, lands on one rectified row; a pinhole
// rectification of the same rig cannot hold the corners behind its plane.
namespace latlon {

const ws::Simulator& FisheyeSimulator() {
  static const ws::Simulator simulator(ws::LoadSimConfig("config/sim/fisheye.yaml"));
  return simulator;
}

const ws::RectifyOptions kLatLon{1.0, {}, ws::RectificationMode::kLatLon};

TEST(LatLonRectification, TrueCornerPairsShareARowBeyond90Degrees) {
  const ws::SimTruth truth = FisheyeSimulator().Truth();
  const ws::Rig rig = truth.rig;
  const cv::Vec2d field = ws::CommonField(rig);
  const ws::Rectification rect = ws::BuildRectification(rig, kLatLon);
  std::printf("[ rectify ] fisheye rig: common field %.1f x %.1f degrees, lat-lon image %d x %d at "
              "%.1f px per radian\n",
              field[0] * 180 / M_PI, field[1] * 180 / M_PI, rect.size.width, rect.size.height, rect.f);
  int lost = 0;
  const RowErrors rows = RowsOfTrueCorners(truth, rig, kLatLon, &lost);
  rows.Print("true corners, fisheye rig, lat-lon");
  EXPECT_EQ(lost, 0);
  EXPECT_GT(rows.count(), 1000);
  EXPECT_LT(rows.worst(), 0.01);
  // Corners past 90 degrees off either camera's axis are among them.
  int beyond_90 = 0;
  for (const ws::SimFrameTruth& frame : truth.frames)
    for (size_t id = 0; frame.kind == "board" && id < frame.left.corners.size(); ++id) {
      if (!frame.left.in_image[id] || !frame.right.in_image[id]) continue;
      const auto ray = ws::Camera(rig.left).Unproject(
          Eigen::Vector2d(frame.left.corners[id].x, frame.left.corners[id].y));
      beyond_90 += ray && (*ray)[2] < 0;
    }
  std::printf("[ rectify ] %d of the pairs lie beyond 90 degrees off the left camera's axis\n", beyond_90);
  EXPECT_GT(beyond_90, 0);

  int behind_the_plane = 0;
  RowsOfTrueCorners(truth, rig, ws::RectifyOptions(), &behind_the_plane);
  std::printf("[ rectify ] pinhole rectification of the same rig: %d pairs have no rectified pixel\n",
              behind_the_plane);
  EXPECT_GT(behind_the_plane, 0);
}

// The common field fills its lat-lon image; one half as large again about
// it reaches past the lenses' field (the model's last knot): those pixels
// are marked invalid and hold no image.
TEST(LatLonRectification, PixelsOutsideTheLensFieldAreInvalid) {
  const ws::Rig rig = FisheyeSimulator().Truth().rig;
  const ws::Rectification fitted = ws::BuildRectification(rig, kLatLon);
  ws::RectifyOptions larger = kLatLon;
  larger.size = cv::Size(fitted.size.width * 3 / 2, fitted.size.height * 3 / 2);
  const ws::Rectification rect = ws::BuildRectification(rig, larger);
  const cv::Mat white(rect.input_size, CV_8UC1, cv::Scalar(255));
  cv::Mat images[2];
  ws::RectifyPair(rect, white, white, &images[0], &images[1]);
  for (int c = 0; c < 2; ++c) {
    const cv::Mat& valid = c ? rect.valid_right : rect.valid_left;
    const cv::Mat& fitted_valid = c ? fitted.valid_right : fitted.valid_left;
    ASSERT_EQ(valid.size(), rect.size);
    const double fraction = cv::countNonZero(valid) / double(rect.size.area());
    const double fitted_fraction = cv::countNonZero(fitted_valid) / double(fitted.size.area());
    std::printf("[ rectify ] valid fraction: common field %.3f, 1.5 times as large %.3f\n",
                fitted_fraction, fraction);
    EXPECT_GT(fitted_fraction, 0.95);
    EXPECT_LT(fraction, 0.9);
    cv::Mat outside, inside;
    cv::bitwise_and(images[c], ~valid, outside);
    EXPECT_EQ(cv::countNonZero(outside), 0) << "an invalid pixel holds image";
    cv::bitwise_and(images[c] < 255, valid, inside);
    EXPECT_LT(cv::countNonZero(inside), 0.01 * cv::countNonZero(valid)) << "valid pixels hold the image";
  }
}

TEST(LatLonRectification, DetectedCornersShareARow) {
  const ws::Simulator& simulator = FisheyeSimulator();
  const ws::SimTruth truth = simulator.Truth();
  const ws::Rig rig = truth.rig;
  const ws::Rectification rect = ws::BuildRectification(rig, kLatLon);
  int frames = 0, boards = 0;
  const auto pairs = DetectedCornerPairs(simulator, truth, rig, rect, &frames, &boards);
  ASSERT_GE(frames, 8);
  // Near the epipoles (psi -> +-90 degrees) every epipolar plane meets: a
  // row there spans an angle cos(psi) times a row at the centre, and a
  // corner's detection error grows in rows by 1 / cos(psi).
  RowErrors rows(rect.size), central(rect.size);
  for (const auto& [l, r] : pairs) {
    rows.Add(l, r);
    if (std::max(std::abs(l.x - rect.cx), std::abs(r.x - rect.cx)) / rect.f <= M_PI / 3)
      central.Add(l, r);
  }
  rows.Print("detected corners, fisheye rig, lat-lon");
  central.Print("detected corners within 60 degrees of the baseline's normal");
  EXPECT_GT(central.count(), 200);
  EXPECT_LT(central.rms(), 0.1);
  EXPECT_LT(central.worst_region_mean(), 0.05) << "no part of the field off on average";
}

TEST(LatLonRectification, CommonFieldOfTheDemoRigAndTheFisheyeRig) {
  const cv::Vec2d demo = ws::CommonField(ws::Simulator(ws::LoadSimConfig("config/sim/default.yaml")).Truth().rig);
  const cv::Vec2d fisheye = ws::CommonField(FisheyeSimulator().Truth().rig);
  std::printf("[ rectify ] common field: demo rig %.1f x %.1f degrees, fisheye rig %.1f x %.1f degrees\n",
              demo[0] * 180 / M_PI, demo[1] * 180 / M_PI, fisheye[0] * 180 / M_PI, fisheye[1] * 180 / M_PI);
  EXPECT_GT(fisheye[0], demo[0]);
  EXPECT_GT(fisheye[0], M_PI * 150 / 180);
}

}  // namespace latlon

}  // namespace
