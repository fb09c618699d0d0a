// stereo-calibrate as a real process, log to log after stereo-capture and
// stereo-detect: OpenCV's own stereo set (opencv-doc) against
// cv::calibrateCamera on the same detections, the same output on every
// replay, and the simulator end to end against its ground truth.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cstdio>
#include <filesystem>
#include <opencv2/calib3d.hpp>

#include "calib_process_support.h"
#include "calib_test_rigs.h"
#include "lcm_io/channels.h"
#include "rig/rig_file.h"
#include "rig/rig_message.h"
#include "sim/ground_truth.h"
#include "widestereo/stereo_calibration_t.hpp"

namespace {

using namespace ws;
using namespace ws::calib;
using namespace ws::calib::test;
using ws::test::ReadFileText;
using ws::test::TempDir;

// cv::calibrateCamera, its default 5-coefficient model, on one camera's views.
double OpenCvRms(const CameraData& camera) {
  std::vector<std::vector<cv::Point3f>> object;
  std::vector<std::vector<cv::Point2f>> image;
  OpenCvViews(camera, &object, &image);
  cv::Mat K, distortion;
  std::vector<cv::Mat> rvecs, tvecs;
  return cv::calibrateCamera(object, image, cv::Size(camera.image_width, camera.image_height), K,
                             distortion, rvecs, tvecs);
}

void PrintTable(const char* title, const nlohmann::json& report) {
  std::printf("%s\n%-10s %10s %10s %10s\n", title, "model", "left", "right", "stereo");
  for (const auto& row : report["table_ii"])
    std::printf("%-10s %10.4f %10.4f %10.4f\n", row["model"].get<std::string>().c_str(),
                row["left_rms_px"].get<double>(), row["right_rms_px"].get<double>(),
                row["stereo_rms_px"].get<double>());
}

// The paper's flow gives each camera its own calibration, as calibrateCamera
// does: the same model (poly6) must reach the same RMS, the B-spline no more.
// So, as calibrateCamera, no corner is left out, the board is flat and the
// lens radial.
TEST(StereoCalibrateProcess, OpenCvStereoSetNoWorseThanCalibrateCamera) {
  const std::string dir = TempDir("calibrate-opencv");
  const std::string corners =
      CaptureAndDetect(dir, "dir:" + ws::test::OpenCvStereoSetDir(), "chessboard:9x6:0.025");
  const auto run = CalibrateOnce(dir, corners, "paper",
                                 {"--model", "all", "--flow", "paper", "--plot-dir", dir,
                                  "--outlier-sigma", "off", "--board-warp", "off", "--nonradial",
                                  "none"});
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("Table II"), std::string::npos) << run.output;
  const StereoData data = ReadCorners(corners);
  const double opencv[2] = {OpenCvRms(data.left), OpenCvRms(data.right)};
  const nlohmann::json report = ReadJson(dir + "/paper.json");
  PrintTable("Table II, opencv-doc stereo set, paper flow [px]", report);
  std::printf("%-10s %10.4f %10.4f (cv::calibrateCamera, 5 coefficients)\n", "opencv", opencv[0],
              opencv[1]);
  ASSERT_EQ(report["models"].size(), 5u);
  for (const auto& model : report["models"]) {
    ASSERT_FALSE(model.contains("error")) << model["model"] << ": " << model["error"];
    // kb4 has no tangential terms: calibrateCamera's model is not its equal.
    const bool pinhole = model["model"] != "kb4" && model["model"] != "bspline_theta";
    for (int c = 0; c < 2; ++c) {
      const auto& camera = model["cameras"][c];
      EXPECT_EQ(camera["views"], 13);
      if (pinhole) {
        EXPECT_LE(camera["rms_px"].get<double>(), opencv[c] * (1 + 1e-4))
            << model["model"] << " " << camera["name"];
      }
    }
    // Every pair is in R, T or reported as not fitting one rig: one pair,
    // the eighth, stands out of corners this close (the right camera's RMS
    // 0.17 px, 0.26 with one saddle scale for the whole board) for every
    // model; kb4, which has no tangential terms, left it out before too.
    EXPECT_EQ(model["stereo"]["views"].get<size_t>() + model["stereo"]["inconsistent_views"].size(),
              13u);
    EXPECT_GE(model["stereo"]["views"], 12);
  }
  // The file holds the model chosen by held-out error (issue #14), one
  // that predicts held-out views as well as the best (on this ordinary lens
  // poly6, poly12 and bspline do so within 0.4 % of each other: which one
  // is chosen follows the folds' small, consistent differences);
  // STEREO_CALIBRATION says the same.
  const Rig file = ReadCalibrationFile(dir + "/paper.yaml");
  double lowest = INFINITY, chosen = INFINITY;
  for (const auto& row : report["table_ii"]) {
    const double heldout = 0.5 * (row["left_heldout_rms_px"].get<double>() +
                                  row["right_heldout_rms_px"].get<double>());
    lowest = std::min(lowest, heldout);
    if (row["chosen"].get<bool>()) chosen = heldout;
  }
  std::printf("chosen %s: held-out %.4f px (lowest %.4f px)\n",
              report["chosen"].get<std::string>().c_str(), chosen, lowest);
  EXPECT_LE(chosen, 1.005 * lowest);
  EXPECT_EQ(ModelName(file.kind()), report["chosen"]);
  const auto published = ws::test::Messages<widestereo::stereo_calibration_t>(
      ws::test::ReadLog(dir + "/paper.lcmlog"), channel::kStereoCalibration);
  ASSERT_EQ(published.size(), 1u);
  const Rig rig = RigFromMessage(published[0]);  // as stereo-match reads it
  EXPECT_EQ(rig.left.fx, file.left.fx);
  EXPECT_EQ(rig.right.distortion.coeffs, file.right.distortion.coeffs);
  EXPECT_EQ(rig.T, file.T);
  EXPECT_EQ(rig.R, file.R);
  for (const char* png : {"/distortion_curves.png", "/residual_map.png", "/knot_curve.png"})
    EXPECT_GT(std::filesystem::file_size(dir + png), 10000u) << png;
}

// Drops "solve_seconds" (wall clock) everywhere.
void DropSolveSeconds(nlohmann::json& j) {
  if (j.is_object()) j.erase("solve_seconds");
  if (j.is_structured())
    for (auto& item : j) DropSolveSeconds(item);
}

TEST(StereoCalibrateProcess, OnceOverALogGivesTheSameCalibrationTwice) {
  const std::string dir = TempDir("calibrate-twice");
  const std::string corners =
      CaptureAndDetect(dir, "dir:" + ws::test::OpenCvStereoSetDir(), "chessboard:9x6:0.025");
  for (const char* name : {"first", "second"}) {
    const auto run = CalibrateOnce(dir, corners, name, {"--model", "all"});
    ASSERT_EQ(run.exit_code, 0) << run.output;
  }
  EXPECT_EQ(ReadFileText(dir + "/first.yaml"), ReadFileText(dir + "/second.yaml"));
  nlohmann::json first = ReadJson(dir + "/first.json"), second = ReadJson(dir + "/second.json");
  DropSolveSeconds(first);
  DropSolveSeconds(second);
  EXPECT_EQ(first.dump(), second.dump());
  std::vector<std::vector<uint8_t>> messages[2];
  int n = 0;
  for (const char* name : {"/first.lcmlog", "/second.lcmlog"}) {
    for (const auto& event : ws::test::ReadLog(dir + name))
      if (event.channel == channel::kStereoCalibration ||
          event.channel == channel::kCalibrationStatus)
        messages[n].push_back(event.data);
    ++n;
  }
  EXPECT_GE(messages[0].size(), 2u);
  EXPECT_EQ(messages[0], messages[1]);
}

// The simulator's default rig (Theia-like mustache lenses, 0.3 m baseline),
// rendered, detected and calibrated, against the simulator's ground truth.
TEST(StereoCalibrateProcess, SimulatorEndToEndRecoversTheTruth) {
  const std::string dir = TempDir("calibrate-sim");
  const std::string truth_path = dir + "/truth.yaml";
  const std::string corners = CaptureAndDetect(
      dir, "sim:" + ws::test::SourceDir() + "/config/sim/default.yaml?truth=" + truth_path,
      "chessboard:9x6:0.05", {"--frame-clock", "--rate", "5"});
  std::filesystem::remove(dir + "/images.lcmlog");  // 86 MB
  const auto run = CalibrateOnce(dir, corners, "sim", {"--model", "all", "--plot-dir", dir});
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const SimTruth truth = LoadSimTruth(truth_path);
  const nlohmann::json report = ReadJson(dir + "/sim.json");
  PrintTable("Table II, simulator end to end (rendered, detected) [px]", report);
  const StereoData data = ReadCorners(corners);
  const Rig file = ReadCalibrationFile(dir + "/sim.yaml");  // the B-spline
  for (const std::string model : {"bspline", "poly6", "poly12"})  // and one file per model
    EXPECT_EQ(ModelName(ReadCalibrationFile(dir + "/sim." + model + ".yaml").kind()), model);
  const Eigen::Vector3d& true_T = truth.rig.T;
  const Eigen::Matrix3d& true_R = truth.rig.R;
  const double baseline_error = std::abs(file.T.norm() / true_T.norm() - 1);
  const double rotation_error = Eigen::AngleAxisd(file.R * true_R.transpose()).angle();
  std::printf("bspline: baseline %.5f m (true %.5f, error %.3f %%), R off by %.4f deg\n",
              file.T.norm(), true_T.norm(), 100 * baseline_error, rotation_error * 180 / M_PI);
  EXPECT_LE(baseline_error, 0.001);
  EXPECT_LE(rotation_error * 180 / M_PI, 0.05);
  for (int c = 0; c < 2; ++c) {
    const ProjectionError error =
        MaxProjectionError(c == 0 ? truth.rig.left : truth.rig.right, c == 0 ? file.left : file.right,
                           c == 0 ? data.left : data.right);
    std::printf("bspline %s: projection error in the observed field %.4f px (%.4f px unturned)\n",
                c == 0 ? "left" : "right", error.turned_px, error.direct_px);
    EXPECT_LE(error.turned_px, 0.1);
  }
  const auto& models = report["models"];
  for (int c = 0; c < 2; ++c)
    EXPECT_GE(models[1]["cameras"][c]["rms_px"].get<double>(),
              3 * models[0]["cameras"][c]["rms_px"].get<double>());
}

}  // namespace
