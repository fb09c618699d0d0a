// stereo-compare (issue #14, calib/evaluate/projection_diff.h) as a user runs it:
// a calibration against itself is 0; against the simulator's truth its
// differences are the test's own evaluation of the same grid; a shift of
// the principal point is nearly a rotation of the camera, which the fit
// takes out.
#include <gtest/gtest.h>

#include <cmath>

#include "calib/calibrate.h"
#include "calib/evaluate/projection_diff.h"
#include "calib/node/solved_rig.h"
#include "calib_process_support.h"
#include "rig/rig_file.h"
#include "sim/simulator.h"
#include "synthetic_rig.h"

namespace {

using namespace ws;
using namespace ws::calib;
using namespace ws::calib::test;
using ws::test::BinDir;
using ws::test::RunCommand;
using ws::test::SourceDir;
using ws::test::TempDir;

struct Files {
  std::string dir, truth, calibration;
  Rig truth_file, calibration_file;
};

// The default simulator rig's truth, and a calibration of synthetic corners
// through the same cameras (0.1 px noise, 13 knots), as files.
const Files& RigFiles() {
  static const Files files = [] {
    Files f;
    f.dir = TempDir("stereo-compare");
    f.truth_file = Simulator(LoadSimConfig(SourceDir() + "/config/sim/default.yaml")).Truth().rig;
    SyntheticRigOptions rig;
    rig.left = GaugeNormalized(f.truth_file.left);
    rig.right = GaugeNormalized(f.truth_file.right);
    rig.R = f.truth_file.R;
    rig.T = f.truth_file.T;
    CalibrationOptions options;
    options.spline.knots = 13;
    options.covariance = false;
    options.cv_folds = 0;
    f.calibration_file = ToRig(CalibrateStereo(MakeSyntheticRig(rig).data, options));
    f.truth = f.dir + "/truth.yaml";
    f.calibration = f.dir + "/calibration.yaml";
    WriteCalibrationFile(f.truth, f.truth_file);
    WriteCalibrationFile(f.calibration, f.calibration_file);
    return f;
  }();
  return files;
}

nlohmann::json Compare(const std::string& a, const std::string& b,
                       std::vector<std::string> extra = {}) {
  const std::string report = RigFiles().dir + "/report.json";
  std::vector<std::string> argv{BinDir() + "/stereo-compare", a, b, "--report", report};
  argv.insert(argv.end(), extra.begin(), extra.end());
  const auto run = RunCommand(argv);
  EXPECT_EQ(run.exit_code, 0) << run.output;
  std::printf("%s", run.output.c_str());
  return ReadJson(report);
}

TEST(StereoCompare, ACalibrationAgainstItselfIsZero) {
  const Files& f = RigFiles();
  const std::string png = f.dir + "/self.png";
  const nlohmann::json report = Compare(f.calibration, f.calibration, {"--plot", png});
  ASSERT_EQ(report["cameras"].size(), 2u);
  for (const auto& camera : report["cameras"]) {
    EXPECT_GT(camera["points"].get<int>(), 64 * 48 / 2);
    EXPECT_LT(camera["max_px"].get<double>(), 1e-6);
    EXPECT_LT(camera["rotation_deg"].get<double>(), 1e-6);
  }
  EXPECT_GT(std::filesystem::file_size(png), 1000u);
}

TEST(StereoCompare, AgainstTheTruthItIsTheTestsOwnEvaluation) {
  const Files& f = RigFiles();
  const nlohmann::json direct = Compare(f.truth, f.calibration, {"--no-rotation"});
  for (int side = 0; side < 2; ++side) {
    const Camera truth(side == 0 ? f.truth_file.left : f.truth_file.right);
    const Camera estimate(side == 0 ? f.calibration_file.left : f.calibration_file.right);
    const auto& camera = direct["cameras"][side];
    const int cols = camera["cols"], rows = camera["rows"];
    const double step_x = double(truth.model().image_width) / cols;
    const double step_y = double(truth.model().image_height) / rows;
    int compared = 0;
    for (int j = 0; j < rows; ++j)
      for (int i = 0; i < cols; ++i) {
        const Eigen::Vector2d q((i + 0.5) * step_x - 0.5, (j + 0.5) * step_y - 0.5);
        const auto& value = camera["diff_px"][j * cols + i];
        const auto ray = truth.Unproject(q);
        const auto pixel = ray ? estimate.Project(*ray) : std::nullopt;
        if (value.is_null()) continue;  // outside the estimate's image
        ASSERT_TRUE(pixel);
        EXPECT_NEAR(value.get<double>(), (*pixel - q).norm(), 1e-9);
        ++compared;
      }
    EXPECT_EQ(compared, camera["points"].get<int>());
    EXPECT_GT(compared, cols * rows * 9 / 10);
  }
  // The fitted rotation only takes out what a turn of the camera explains.
  const nlohmann::json turned = Compare(f.truth, f.calibration);
  for (int side = 0; side < 2; ++side) {
    EXPECT_LE(turned["cameras"][side]["rms_px"].get<double>(),
              direct["cameras"][side]["rms_px"].get<double>() + 1e-9);
    EXPECT_LT(turned["cameras"][side]["median_px"].get<double>(), 0.05);
  }
}

// The RMS of a report's differences within `radius` px of the image centre.
double CentralRms(const nlohmann::json& camera, const CameraModel& model, double radius) {
  const int cols = camera["cols"], rows = camera["rows"];
  const double step_x = double(model.image_width) / cols, step_y = double(model.image_height) / rows;
  const Eigen::Vector2d centre((model.image_width - 1) / 2.0, (model.image_height - 1) / 2.0);
  double sum = 0;
  int n = 0;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < cols; ++i) {
      const Eigen::Vector2d q((i + 0.5) * step_x - 0.5, (j + 0.5) * step_y - 0.5);
      const auto& value = camera["diff_px"][j * cols + i];
      if ((q - centre).norm() > radius || value.is_null()) continue;
      sum += value.get<double>() * value.get<double>();
      ++n;
    }
  return n ? std::sqrt(sum / n) : NAN;
}

TEST(StereoCompare, NearTheCentreAPrincipalPointShiftIsARotation) {
  const Files& f = RigFiles();
  Rig shifted = f.calibration_file;
  shifted.left.cx += 1.0;
  shifted.right.cx += 1.0;
  const std::string path = f.dir + "/shifted.yaml";
  WriteCalibrationFile(path, shifted);
  const nlohmann::json direct = Compare(f.calibration, path, {"--no-rotation"});
  const nlohmann::json turned = Compare(f.calibration, path);
  const double radius = DefaultFitRadius(WidestereoProjection(f.calibration_file.left));
  for (int side = 0; side < 2; ++side) {
    EXPECT_NEAR(CentralRms(direct["cameras"][side], f.calibration_file.left, radius), 1.0, 0.01);
    EXPECT_LT(CentralRms(turned["cameras"][side], f.calibration_file.left, radius), 0.1);
    // A turn of about 1 / fx radians.
    EXPECT_NEAR(turned["cameras"][side]["rotation_deg"].get<double>(),
                180 / M_PI / f.calibration_file.left.fx, 0.05);
  }
}

TEST(StereoCompare, RefusesCamerasOfAnotherSize) {
  const Files& f = RigFiles();
  Rig other = f.calibration_file;
  other.left.image_width /= 2;
  other.right.image_width /= 2;
  const std::string path = f.dir + "/other.yaml";
  WriteCalibrationFile(path, other);
  const auto run = RunCommand({BinDir() + "/stereo-compare", f.calibration, path});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.output.find("differ in size"), std::string::npos) << run.output;
}

// Where no grid point projects into both cameras' images (the second's
// principal point two image widths across: every ray lands right of its
// image), there is nothing to compare: an error, not 0 px over 0 points.
TEST(StereoCompare, RefusesToReportADifferenceOverNothing) {
  const Files& f = RigFiles();
  Rig shifted = f.calibration_file;
  for (CameraModel* camera : {&shifted.left, &shifted.right}) camera->cx = 2.0 * camera->image_width;
  const std::string path = f.dir + "/elsewhere.yaml";
  WriteCalibrationFile(path, shifted);
  const auto run = RunCommand({BinDir() + "/stereo-compare", f.calibration, path, "--no-rotation"});
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_NE(run.output.find("nothing to compare"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("over 0 grid points"), std::string::npos) << run.output;
}

}  // namespace
