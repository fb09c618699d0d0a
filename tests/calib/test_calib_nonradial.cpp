// The lens model's non-radial field (models/nonradial_field.h) end to end on
// a lens no radial curve describes: the Theia-like rig with each sensor
// tilted in its mount (config/sim/tilted-sensor.yaml, sim/sensor_tilt.h),
// rendered, detected and calibrated with the defaults, against the same
// views calibrated radially; each against the simulator's ground truth at
// the true ray of every detected corner.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "calib_process_support.h"
#include "calib_test_rigs.h"
#include "sim/ground_truth.h"

namespace {

using namespace ws;
using namespace ws::calib;
using namespace ws::calib::test;

std::vector<Eigen::Vector2d> Corners(const CameraData& camera) {
  std::vector<Eigen::Vector2d> out;
  for (const auto& view : camera.views) out.insert(out.end(), view.image.begin(), view.image.end());
  return out;
}

// Measured: radially 2.00 / 2.11 px off the truth; with the defaults an
// 11 x 8 field on both cameras, 0.44 / 0.42 px (fitted 0.024 / 0.025 px).
// The same views with exact corners and a 16 x 12 field come within 0.067 px
// of the truth: a tilted sensor on this nearly rectilinear lens is nearly a
// turn of the camera, and the views tell the two apart only weakly.
TEST(CalibNonRadial, ATiltedSensorIsTakenUpByTheFieldWhereTheRadialModelIsOff) {
  const std::string dir = ws::test::TempDir("calibrate-tilted-sensor");
  const std::string truth_path = dir + "/truth.yaml";
  const std::string corners = CaptureAndDetect(
      dir, "sim:" + ws::test::SourceDir() + "/config/sim/tilted-sensor.yaml?truth=" + truth_path,
      "chessboard:9x6:0.05", {"--frame-clock", "--rate", "5", "--count", "30"});
  std::filesystem::remove(dir + "/images.lcmlog");
  const SimTruth truth = LoadSimTruth(truth_path);
  const StereoData data = ReadCorners(corners);
  double worst[2] = {0, 0};  // radial only, then the defaults
  for (const FieldRule rule : {FieldRule::kNone, FieldRule::kAuto}) {
    CalibrationOptions options;
    options.model = "bspline";
    options.nonradial = rule;
    options.covariance = false;
    const StereoCalibration solved = CalibrateStereo(data, options);
    for (int c = 0; c < 2; ++c) {
      const CameraCalibration& camera = c == 0 ? solved.left : solved.right;
      const ProjectionError error = CornerRayError(c == 0 ? truth.left : truth.right, camera.model,
                                                   Corners(c == 0 ? data.left : data.right));
      const NonRadial& field = camera.model.nonradial;
      std::printf("tilted sensor, %-5s %-11s field %2d x %2d: rms %.4f px, held-out %.4f px, "
                  "projection error vs truth at the corners' true rays %.4f px\n",
                  camera.name.c_str(), rule == FieldRule::kNone ? "radial only" : "defaults",
                  field.cols, field.rows, camera.rms_px, camera.heldout_rms_px, error.turned_px);
      worst[rule == FieldRule::kAuto] = std::max(worst[rule == FieldRule::kAuto], error.turned_px);
      if (rule == FieldRule::kAuto) EXPECT_FALSE(field.empty()) << camera.name;
    }
  }
  EXPECT_GE(worst[0], 1.0) << "the radial model alone is visibly off";
  EXPECT_LE(worst[1], 0.25 * worst[0]);
}

}  // namespace
