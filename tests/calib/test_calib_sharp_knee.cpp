// The sharp-knee rig (config/sim/sharp-knee.yaml, issue #14) end to end:
// stereo-capture renders it, stereo-detect finds the boards, stereo-calibrate
// --once solves it with its default options (--knots auto) and with the old
// fixed 13 coefficients; each against the simulator's ground truth at the
// true ray of every detected corner.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>

#include "calib_process_support.h"
#include "calib_test_rigs.h"
#include "rig/rig_file.h"
#include "sim/ground_truth.h"

namespace {

using namespace ws;
using namespace ws::calib;
using namespace ws::calib::test;
using ws::test::TempDir;

std::vector<Eigen::Vector2d> Corners(const CameraData& camera) {
  std::vector<Eigen::Vector2d> out;
  for (const auto& view : camera.views) out.insert(out.end(), view.image.begin(), view.image.end());
  return out;
}

// Each camera's projection error against the truth at the true rays of its
// detected corners, per --knots value, with stereo-calibrate's defaults
// otherwise; prints them with the fitted and held-out RMS and checks what
// every automatic choice must show (the report's curve, a held-out RMS
// within 15 % of the fitted one).
struct KnotRun {
  double worst_px = 0;  // over both cameras
  size_t fewest_coeffs = 1000;
};
// (The 30 board frames only: the Theia-like config's wall frames after them
// are not rendered.)
std::map<std::string, KnotRun> RenderDetectCalibrate(const std::string& config,
                                                      const std::vector<std::string>& knot_values) {
  const std::string dir = TempDir("calibrate-" + config);
  const std::string truth_path = dir + "/truth.yaml";
  const std::string corners = CaptureAndDetect(
      dir, "sim:" + ws::test::SourceDir() + "/config/sim/" + config + ".yaml?truth=" + truth_path,
      "chessboard:9x6:0.05", {"--frame-clock", "--rate", "5", "--count", "30"});
  std::filesystem::remove(dir + "/images.lcmlog");
  const SimTruth truth = LoadSimTruth(truth_path);
  const StereoData data = ReadCorners(corners);
  std::map<std::string, KnotRun> out;
  // The same views with every detected corner moved to its true pixel,
  // calibrated in this process with the defaults: what is left is the
  // method's own error (a view reaching past the others' field once lost
  // its pose here: 0.33 px at its corners).
  StereoData exact = data;
  for (size_t j = 0; j < exact.left.views.size(); ++j)
    for (int c = 0; c < 2; ++c) {
      ws::calib::BoardView& view = (c == 0 ? exact.left : exact.right).views[j];
      const SimViewTruth& true_view = c == 0 ? truth.frames[j].left : truth.frames[j].right;
      for (int i = 0; i < view.size(); ++i) {
        const cv::Point2d& u = true_view.corners.at(size_t(view.ids[i]));
        view.image[i] = {u.x, u.y};
      }
    }
  CalibrationOptions defaults;
  defaults.covariance = false;
  const StereoCalibration solved = CalibrateStereo(exact, defaults);
  for (int c = 0; c < 2; ++c) {
    const ProjectionError error =
        CornerRayError(c == 0 ? truth.rig.left : truth.rig.right, c == 0 ? solved.left.model : solved.right.model,
                       Corners(c == 0 ? exact.left : exact.right));
    std::printf("%s exact corners %-5s: projection error vs truth %.4f px\n", config.c_str(),
                c == 0 ? "left" : "right", error.turned_px);
    out["exact"].worst_px = std::max(out["exact"].worst_px, error.turned_px);
  }
  for (const std::string& knots : knot_values) {
    SCOPED_TRACE(config + " --knots " + knots);
    const std::string name = "knots-" + knots;
    const auto run = CalibrateOnce(dir, corners, name, {"--model", "bspline", "--knots", knots});
    EXPECT_EQ(run.exit_code, 0) << run.output;
    if (run.exit_code != 0) continue;
    const Rig file = ReadCalibrationFile(dir + "/" + name + ".yaml");
    const nlohmann::json report = ReadJson(dir + "/" + name + ".json");
    for (int c = 0; c < 2; ++c) {
      const auto& camera = report["cameras"][c];
      const ProjectionError error =
          CornerRayError(c == 0 ? truth.rig.left : truth.rig.right, c == 0 ? file.left : file.right,
                         Corners(c == 0 ? data.left : data.right));
      const double rms = camera["rms_px"], heldout = camera["heldout_rms_px"];
      const size_t coeffs = camera["alpha"].size() - 2;
      std::printf("%s --knots %-4s %-5s %zu coefficients: rms %.4f px, held-out %.4f px, "
                  "projection error vs truth at the corners' true rays %.4f px\n",
                  config.c_str(), knots.c_str(), c == 0 ? "left" : "right", coeffs, rms, heldout,
                  error.turned_px);
      out[knots].worst_px = std::max(out[knots].worst_px, error.turned_px);
      out[knots].fewest_coeffs = std::min(out[knots].fewest_coeffs, coeffs);
      if (knots == "auto") {
        EXPECT_GT(camera["knot_curve"].size(), 2u);
        // A radially symmetric lens: no non-radial field (report.h).
        EXPECT_GT(camera["field_curve"].size(), 1u);
        EXPECT_EQ(camera["field_chosen"], 0);
        // The right model predicts views it did not see as well as those it fitted.
        EXPECT_LE(heldout, 1.15 * rms);
      }
    }
  }
  return out;
}

TEST(CalibSharpKnee, AutomaticKnotsFollowAKneeThirteenCannot) {
  auto runs = RenderDetectCalibrate("sharp-knee", {"auto", "13"});
  EXPECT_GT(runs["auto"].fewest_coeffs, 13u) << "the knee needs more than 13";
  // 13 coefficients visibly under-fit this lens; the automatic choice
  // matches the truth to 0.08 px at every corner ray (issue #14; measured
  // 0.036 and 0.060 px, the corners refined to their saddle points, 0.033
  // px RMS off the truth).
  EXPECT_LE(runs["auto"].worst_px, 0.08);
  // Exact corners: measured 0.009 / 0.001 px.
  EXPECT_LE(runs["exact"].worst_px, 0.02);
  EXPECT_GE(runs["13"].worst_px, 5 * runs["auto"].worst_px);
}

TEST(CalibSharpKnee, OnTheTheiaLikeLensTheChoiceIsNoWorseThanThirteen) {
  auto runs = RenderDetectCalibrate("default", {"auto", "13"});
  // No worse: within a tenth of a noise-level difference (0.01 px).
  EXPECT_LE(runs["auto"].worst_px, runs["13"].worst_px + 0.01);
  EXPECT_LE(runs["exact"].worst_px, 0.02);  // measured 0.0002 / 0.001 px
}

}  // namespace
