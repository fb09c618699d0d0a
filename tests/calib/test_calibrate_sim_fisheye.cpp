// The simulator's 200-degree fisheye rig (config/sim/fisheye.yaml) end to
// end: stereo-capture renders it, stereo-detect finds the boards,
// stereo-calibrate --once solves bspline_theta (and kb4 on the same corners,
// for comparison), each against the simulator's ground truth.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "calib_process_support.h"
#include "calib_test_rigs.h"
#include "rig/rig_file.h"
#include "sim/ground_truth.h"

namespace {

using namespace ws;
using namespace ws::calib;
using namespace ws::calib::test;
using ws::test::TempDir;

TEST(CalibSimFisheye, RenderedDetectedAndCalibratedRecoversTheTruth) {
  const std::string dir = TempDir("calibrate-sim-fisheye");
  const std::string truth_path = dir + "/truth.yaml";
  const std::string corners = CaptureAndDetect(
      dir, "sim:" + ws::test::SourceDir() + "/config/sim/fisheye.yaml?truth=" + truth_path,
      "chessboard:9x6:0.05", {"--frame-clock", "--rate", "5"});
  std::filesystem::remove(dir + "/images.lcmlog");  // 80 MB
  const SimTruth truth = LoadSimTruth(truth_path);
  const StereoData data = ReadCorners(corners);
  const double true_baseline = truth.rig.T.norm();
  for (const std::string model : {"bspline_theta", "kb4"}) {
    SCOPED_TRACE(model);
    // The knee (4.6 degrees wide) needs finer knots than the default 13 over
    // the 100-degree field (as in test_calib_fisheye.cpp): here 13 give
    // 0.15 / 0.15 px, 17 0.10 / 0.05 px, 21 0.09 / 0.05 px, 25 0.09 / 0.05 px
    // (the rest is the detected corners' own error, ~0.06 px RMS).
    const auto run = CalibrateOnce(dir, corners, model, {"--model", model, "--knots", "21"});
    ASSERT_EQ(run.exit_code, 0) << run.output;
    const Rig file = ReadCalibrationFile(dir + "/" + model + ".yaml");
    const nlohmann::json report = ReadJson(dir + "/" + model + ".json");
    const double baseline_error = std::abs(file.T.norm() / true_baseline - 1);
    for (int c = 0; c < 2; ++c) {
      const auto& camera = report["cameras"][c];
      const ProjectionError error = MaxProjectionError(c == 0 ? truth.rig.left : truth.rig.right,
                                                       c == 0 ? file.left : file.right,
                                                       c == 0 ? data.left : data.right);
      const double theta_deg = camera["max_observed_radius"].get<double>() * 180 / M_PI;
      std::printf("%-13s %-5s rms %.4f px, %d views, largest observed theta %.1f deg, projection error in "
                  "the observed field %.4f px (%.4f px unturned), baseline error %.4f %%\n",
                  model.c_str(), c == 0 ? "left" : "right", camera["rms_px"].get<double>(),
                  camera["views"].get<int>(), theta_deg, error.turned_px, error.direct_px, 100 * baseline_error);
      EXPECT_GT(theta_deg, 90) << "corners beyond 90 degrees were used";
      if (model == "bspline_theta") {
        EXPECT_LE(error.turned_px, 0.1);
        EXPECT_GE(camera["views"].get<int>(), 25);
      }
    }
    if (model == "bspline_theta") {
      EXPECT_LE(baseline_error, 0.001);
    }
  }
}

}  // namespace
