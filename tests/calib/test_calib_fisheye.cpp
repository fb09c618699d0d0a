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

CalibrationOptions WithModel(const std::string& model) {
  CalibrationOptions options;
  options.model = model;
  // The knee (4.6 degrees wide) needs finer knots than the default 13 over
  // the 100-degree field: 13 give 0.13 / 0.15 px, 17 give 0.09 / 0.10 px.
  options.knots = 21;
  return options;
}

TEST(CalibFisheye, BsplineThetaMatchesTheTruthBeyond90Degrees) {
  const SyntheticRigOptions truth = FisheyeRig();
  const SyntheticRig rig = MakeSyntheticRig(truth);
  const StereoCalibration result = CalibrateStereo(rig.data, WithModel("bspline_theta"));
  const CameraCalibration* cameras[2] = {&result.left, &result.right};
  const CameraModel* true_models[2] = {&truth.left, &truth.right};
  const CameraData* data[2] = {&rig.data.left, &rig.data.right};
  for (int c = 0; c < 2; ++c) {
    const CameraCalibration& camera = *cameras[c];
    const double floor = TruthRms(truth, rig, c);
    const ProjectionError error = MaxProjectionError(*true_models[c], camera.model, *data[c]);
    std::printf(
        "bspline_theta %s: rms %.4f px (truth %.4f), projection error in the observed field "
        "%.4f px (%.4f px without the best rotation), %d of %zu views, largest observed theta "
        "%.1f deg\n",
        camera.name.c_str(), camera.rms_px, floor, error.turned_px, error.direct_px, camera.views,
        data[c]->views.size(), camera.max_observed_radius * 180 / M_PI);
    EXPECT_NEAR(camera.rms_px, floor, 0.1 * floor) << camera.name;
    EXPECT_LE(error.turned_px, 0.1) << camera.name;
    EXPECT_GT(camera.max_observed_radius, M_PI / 2) << "corners beyond 90 degrees were used";
    EXPECT_TRUE(camera.skipped.empty()) << camera.name << ": " << camera.skipped.front();
    ExpectParametersWithin(*true_models[c], camera, 3.0, false);
  }
  const double baseline_error = std::abs(result.T.norm() / truth.T.norm() - 1);
  std::printf("baseline %.6f m (true %.6f): error %.4f %%\n", result.T.norm(), truth.T.norm(),
              100 * baseline_error);
  EXPECT_LE(baseline_error, 0.001);
}

TEST(CalibFisheye, Kb4StartsOnTheSameViewsButCannotFollowTheKnee) {
  const SyntheticRigOptions truth = FisheyeRig();
  const SyntheticRig rig = MakeSyntheticRig(truth);
  const StereoCalibration kb4 = CalibrateStereo(rig.data, WithModel("kb4"));
  const double floor = TruthRms(truth, rig, 0);
  const ProjectionError error = MaxProjectionError(truth.left, kb4.left.model, rig.data.left);
  std::printf("kb4 left: rms %.4f px (truth %.4f), projection error %.4f px, %d views\n",
              kb4.left.rms_px, floor, error.turned_px, kb4.left.views);
  EXPECT_EQ(kb4.left.views, static_cast<int>(rig.data.left.views.size()));
  EXPECT_EQ(kb4.left.model.p1, 0.0);
  EXPECT_EQ(kb4.left.model.p2, 0.0);
  EXPECT_GT(kb4.left.rms_px, 1.2 * floor) << "the knee is beyond a 4-term polynomial in theta";
}

}  // namespace
