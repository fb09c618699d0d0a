// Calibration of a synthetic 200-degree fisheye rig (projected board corners,
// 0.1 px noise, no images) whose lens has a knee in theta: bspline_theta
// follows it over the whole observed field, boards beyond 90 degrees
// included; kb4 (cv::fisheye's model) can only approach it.
#include <gtest/gtest.h>

#include <cstdio>

#include "calib_test_rigs.h"

namespace {

using namespace ws;
using namespace ws::calib;
using namespace ws::calib::test;

CalibrationOptions WithModel(ws::ModelKind model) {
  CalibrationOptions options;
  options.model = model;
  // The knee (4.6 degrees wide) needs finer knots than the default 13 over
  // the 100-degree field: 13 give 0.13 / 0.15 px, 17 give 0.09 / 0.10 px.
  options.spline.knots = 21;
  // The radial models alone: a non-radial field over the image would take up
  // part of kb4's misfit at the knee, which is what the kb4 test measures.
  options.nonradial = FieldRule::kNone;
  return options;
}

TEST(CalibFisheye, BsplineThetaMatchesTheTruthBeyond90Degrees) {
  const SyntheticRigOptions truth = FisheyeRig();
  const SyntheticRig rig = MakeSyntheticRig(truth);
  const StereoCalibration result = CalibrateStereo(rig.data, WithModel(ws::ModelKind::kBsplineTheta));
  ExpectCamerasMatchTruth(truth, rig, result);  // the radius is theta, in radians
  for (const CameraCalibration* camera : {&result.left, &result.right}) {
    EXPECT_GT(camera->max_observed_radius, M_PI / 2) << "corners beyond 90 degrees were used";
    EXPECT_TRUE(camera->skipped.empty()) << camera->name << ": " << camera->skipped.front();
  }
  const double baseline_error = std::abs(result.T.norm() / truth.T.norm() - 1);
  std::printf("baseline %.6f m (true %.6f): error %.4f %%\n", result.T.norm(), truth.T.norm(),
              100 * baseline_error);
  EXPECT_LE(baseline_error, 0.001);
}

TEST(CalibFisheye, Kb4StartsOnTheSameViewsButCannotFollowTheKnee) {
  const SyntheticRigOptions truth = FisheyeRig();
  const SyntheticRig rig = MakeSyntheticRig(truth);
  const StereoCalibration kb4 = CalibrateStereo(rig.data, WithModel(ws::ModelKind::kKb4));
  const double floor = TruthRms(truth, rig, 0);
  const ProjectionError error = MaxProjectionError(truth.left, kb4.left.model, rig.data.left);
  std::printf("kb4 left: rms %.4f px (truth %.4f), projection error %.4f px, %d views\n",
              kb4.left.rms_px, floor, error.turned_px, kb4.left.views);
  EXPECT_EQ(kb4.left.views, static_cast<int>(rig.data.left.views.size()));
  EXPECT_EQ(kb4.left.model.p1, 0.0);
  EXPECT_EQ(kb4.left.model.p2, 0.0);
  EXPECT_GT(kb4.left.rms_px, 1.2 * floor) << "the knee is beyond a 4-term polynomial in theta";
}

// Every model on boards that reach 100 degrees off the axis: the angle
// models solve first and find corners past 90 degrees, where a pinhole
// radius tan(theta) has no value, so the pinhole-radius models are listed
// as not tried (not failed) and cost nothing.
TEST(CalibFisheye, PinholeRadiusModelsAreNotTriedBeyond90Degrees) {
  const SyntheticRig rig = MakeSyntheticRig(FisheyeRig());
  CalibrationOptions options;
  options.nonradial = FieldRule::kNone;
  const ModelCalibrations all = CalibrateStereoAllModels(rig.data, options, ModelKinds());
  ASSERT_EQ(all.solved.size(), 2u);
  for (const StereoCalibration& solved : all.solved) EXPECT_TRUE(Traits(solved.model).angle) << solved.model;
  ASSERT_EQ(all.failed.size(), 3u);
  for (const ModelFailure& failure : all.failed) {
    EXPECT_TRUE(failure.not_tried) << failure.model << ": " << failure.error;
    EXPECT_NE(failure.error.find("tan(theta) has none"), std::string::npos) << failure.error;
  }
}

}  // namespace
