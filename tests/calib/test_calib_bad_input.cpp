// Input no calibration can come from gives a clear CalibrationError; input
// that is partly bad is used without its bad part, which is counted.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "calib/node/calibrate_node.h"
#include "calib/node/corners_message.h"
#include "calib_test_rigs.h"

namespace {

using namespace ws;
using namespace ws::calib;
using namespace ws::calib::test;

// 15 views of the barrel rig, solved with poly6 (fast).
struct BarrelViews : ::testing::Test {
  void SetUp() override {
    truth = BarrelRig();
    truth.views = 15;
    rig = MakeSyntheticRig(truth);
    options.model = ModelKind::kPoly6;
  }
  SyntheticRigOptions truth;
  SyntheticRig rig;
  CalibrationOptions options;
};

// Runs f, expecting a CalibrationError whose message contains every part.
template <class F>
void ExpectCalibrationError(F f, const std::vector<std::string>& parts) {
  try {
    f();
    ADD_FAILURE() << "no CalibrationError";
  } catch (const CalibrationError& e) {
    for (const auto& part : parts)
      EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

TEST_F(BarrelViews, TwoViewsAreTooFew) {
  rig.data.left.views.resize(2);
  ExpectCalibrationError([&] { CalibrateCamera(rig.data.left, options); },
                         {"left camera: 2 usable views", "at least 3 needed"});
}

TEST_F(BarrelViews, CollinearViewsAreSkippedAndNamed) {
  for (int v : {0, 1}) {  // keep the first row of the board only: a line of corners
    BoardView& view = rig.data.left.views[v];
    BoardView line;
    for (int i = 0; i < view.size(); ++i)
      if (view.object[i].y() == 0) {
        line.ids.push_back(view.ids[i]);
        line.object.push_back(view.object[i]);
        line.image.push_back(view.image[i]);
      }
    ASSERT_GE(line.size(), 6);
    view = line;
  }
  const CameraCalibration result = CalibrateCamera(rig.data.left, options);
  EXPECT_EQ(result.views, 13);
  ASSERT_GE(result.skipped.size(), 2u);
  EXPECT_NE(result.skipped[0].find("view 0: the corners are (nearly) collinear"), std::string::npos)
      << result.skipped[0];
  EXPECT_LT(result.rms_px, 0.16);

  for (BoardView& view : rig.data.left.views) view = rig.data.left.views[0];
  ExpectCalibrationError([&] { CalibrateCamera(rig.data.left, options); },
                         {"0 usable views", "collinear"});
}

TEST_F(BarrelViews, NonFiniteCornersAreDroppedAndCounted) {
  const double floor = TruthRms(truth, rig, 0);
  rig.data.left.views[3].image[0].x() = NAN;
  rig.data.left.views[4].image[5].y() = INFINITY;
  rig.data.left.views[4].object[6].x() = NAN;
  for (auto& p : rig.data.left.views[5].image) p = Eigen::Vector2d(NAN, NAN);
  const int view5 = rig.data.left.views[5].size();
  const CameraCalibration result = CalibrateCamera(rig.data.left, options);
  EXPECT_EQ(result.invalid_points, 3 + view5);
  EXPECT_EQ(result.views, 14);
  EXPECT_TRUE(std::isfinite(result.rms_px));
  EXPECT_NEAR(result.rms_px, floor, 0.1 * floor);
  for (const double v : result.model.Intrinsics()) EXPECT_TRUE(std::isfinite(v));
}

TEST_F(BarrelViews, ABoardSeenByOneCameraOnly) {
  // Views 0-4 seen by the left camera only: they serve its intrinsics alone.
  for (int v = 0; v < 5; ++v) rig.data.right.views[v] = BoardView();
  const StereoCalibration result = CalibrateStereo(rig.data, options);
  int both = 0;
  for (int v = 0; v < rig.data.size(); ++v)
    both += !rig.data.left.views[v].empty() && !rig.data.right.views[v].empty();
  EXPECT_EQ(result.views, both);
  EXPECT_EQ(result.left.views, 15);
  EXPECT_LT(result.view_rms[0], 0);  // not a stereo view
  EXPECT_LE(std::abs(result.T.norm() / truth.T.norm() - 1), 0.002);

  // The right camera never sees the board: nothing to calibrate it from.
  for (BoardView& view : rig.data.right.views) view = BoardView();
  ExpectCalibrationError([&] { CalibrateStereo(rig.data, options); },
                         {"right camera: 0 usable views"});
}

TEST_F(BarrelViews, ParallelBoardsAreDegenerate) {
  // The board fronto-parallel in every view, only moved around: Zhang's
  // method cannot tell the focal length.
  const Camera camera(truth.left);
  CameraData data;
  data.name = "left";
  data.image_width = truth.left.image_width;
  data.image_height = truth.left.image_height;
  for (int v = 0; v < 8; ++v) {
    const Pose pose = Pose::FromRt(Eigen::Matrix3d::Identity(),
                                   Eigen::Vector3d(-0.2 + 0.05 * v, -0.15 + 0.02 * v, 0.8));
    BoardView view;
    for (int r = 0; r < 6; ++r)
      for (int c = 0; c < 9; ++c) {
        const Eigen::Vector3d X(0.04 * c, 0.04 * r, 0);
        const auto pixel = camera.Project(pose * X);
        view.ids.push_back(r * 9 + c);
        view.object.push_back(X);
        view.image.push_back(*pixel);
      }
    data.views.push_back(view);
  }
  ExpectCalibrationError([&] { CalibrateCamera(data, options); }, {"parallel", "tilt the board"});
}

TEST_F(BarrelViews, OutliersAreRejectedAndCounted) {
  // 12 corners 5 px off (a detector that jumped to the wrong corner).
  const double floor = TruthRms(truth, rig, 0);
  int moved = 0;
  for (int v = 2; v < 14; v += 3)
    for (int i : {1, 7, 13}) {
      rig.data.left.views[v].image[i] += Eigen::Vector2d(3.0, -4.0);
      ++moved;
    }
  auto moved_left_out = [](const CameraCalibration& c) {
    int n = 0;
    for (const CornerResidual& r : c.residuals)
      n += r.outlier && (r.view - 2) % 3 == 0 && (r.index == 1 || r.index == 7 || r.index == 13);
    return n;
  };
  options.outliers = OutlierRule::kOff;
  options.nonradial = FieldRule::kNone;  // poly6 on a poly6 lens
  const CameraCalibration plain = CalibrateCamera(rig.data.left, options);
  EXPECT_EQ(plain.outliers, 0);
  EXPECT_GT(plain.rms_px, 1.5 * floor);
  // Chauvenet's criterion (the default) expects half a noise corner beyond
  // its level: the moved ones and at most a few more (here one).
  options.outliers = OutlierRule::kChauvenet;
  const CameraCalibration chauvenet = CalibrateCamera(rig.data.left, options);
  EXPECT_GE(chauvenet.outliers, moved);
  EXPECT_LE(chauvenet.outliers, moved + 3);
  EXPECT_EQ(moved_left_out(chauvenet), moved);
  options.outliers = OutlierRule::kSigma;
  options.outlier_sigma = 5;
  const CameraCalibration robust = CalibrateCamera(rig.data.left, options);
  EXPECT_EQ(robust.outliers, moved);
  EXPECT_EQ(moved_left_out(robust), moved);
  EXPECT_NEAR(robust.rms_px, floor, 0.1 * floor);

  // A robust loss instead: the moved corners pull the camera far less.
  options.outliers = OutlierRule::kOff;
  options.robust_loss = RobustLoss::kCauchy;
  options.robust_scale_px = 0.5;
  const CameraCalibration cauchy = CalibrateCamera(rig.data.left, options);
  // How far each fit is from the corners that were not moved.
  auto good_rms = [&](const CameraCalibration& c) {
    double sum = 0;
    int n = 0;
    for (const CornerResidual& r : c.residuals)
      if (!((r.view - 2) % 3 == 0 && (r.index == 1 || r.index == 7 || r.index == 13))) {
        sum += r.residual.squaredNorm();
        ++n;
      }
    return std::sqrt(sum / n);
  };
  std::printf(
      "rms over the corners not moved: least squares %.4f px, Cauchy loss %.4f px, "
      "rejection %.4f px (noise floor %.4f px)\n",
      good_rms(plain), good_rms(cauchy), good_rms(robust), floor);
  EXPECT_GT(good_rms(plain), good_rms(cauchy));
  EXPECT_NEAR(good_rms(cauchy), floor, 0.1 * floor);
}

TEST(CalibBadInput, ImageSizeChangesAndBadOptionsAreRefused) {
  widestereo::stereo_corners_t msg{};
  msg.left.n = 1;
  msg.left.ids = {0};
  msg.left.image_points = {{1.0, 2.0}};
  msg.left.object_points = {{0, 0, 0}};
  msg.left.image_width = 640;
  msg.left.image_height = 480;
  StereoData data;
  AddStereoCorners(data, msg);
  msg.left.image_width = 1280;
  ExpectCalibrationError([&] { AddStereoCorners(data, msg); }, {"1280x480", "640x480"});

  CalibrationOptions options;
  // An unknown model is refused where its name enters (--model, "solve model=").
  ExpectCalibrationError([&] { ParseModelList("fisheye"); }, {"unknown model 'fisheye'"});
  options.spline.knots = 1;
  ExpectCalibrationError([&] { CalibrateStereo(data, options); }, {"2 to 64 knots"});

  msg.left.image_width = 640;
  msg.left.n = 5;  // more corners claimed than given: refused, never read past the arrays
  ExpectCalibrationError([&] { AddStereoCorners(data, msg); }, {"n = 5 but 1 ids"});
}

}  // namespace
