// stereo-health as a batch filter over rendered logs of the simulated rig
// (issue #17): the true calibration is ok, the right camera pitched or
// rolled in the calibration is misaligned, and --refine repairs a pitched
// one back to the truth.
#include <gtest/gtest.h>

#include <cstdio>

#include "health_fixtures.h"
#include "lcm_io/channels.h"
#include "match_fixtures.h"
#include "rig/rig_file.h"
#include "sim/ground_truth.h"
#include "test_support.h"

namespace {

using namespace ws::test;

const Eigen::Vector3d kPitch = Eigen::Vector3d::UnitX(), kRoll = Eigen::Vector3d::UnitZ();

class HealthReplay : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new std::string(TempDir("health-replay"));
    RenderScene("config/sim/default.yaml", 8, *dir_, "board");  // the first 8 board poses
    RenderScene("config/sim/wall.yaml", 3, *dir_, "wall");
    truth_ = new ws::Rig(ws::LoadSimTruth(*dir_ + "/wall.truth.yaml").rig);
  }
  static void TearDownTestSuite() {
    delete truth_;
    delete dir_;
  }

  static std::string Log(const std::string& scene) { return *dir_ + "/" + scene + ".lcmlog"; }
  static std::string Calibration(const ws::Rig& rig, const std::string& name) {
    const std::string path = *dir_ + "/" + name + ".yaml";
    WriteCalibrationFile(path, rig);
    return path;
  }
  static HealthRun Run(const std::string& scene, const std::string& calib, const std::string& name,
                       std::vector<std::string> args = {}) {
    HealthRun run = RunHealth(*dir_, Log(scene), calib, name, std::move(args));
    EXPECT_FALSE(run.report.is_null()) << run.output;
    if (!run.report.is_null())
      std::printf("[ health ] %-22s %-5s verdict %-10s median |dy| %.3f px, p95 %.3f px, %d matches in %d frames\n",
                  name.c_str(), scene.c_str(), run.report["verdict"].get<std::string>().c_str(),
                  run.report["dy_median_px"].get<double>(), run.report["dy_p95_px"].get<double>(),
                  run.report["matches"].get<int>(), run.report["frames"].get<int>());
    return run;
  }

  static std::string* dir_;
  static ws::Rig* truth_;
};

std::string* HealthReplay::dir_ = nullptr;
ws::Rig* HealthReplay::truth_ = nullptr;

TEST_F(HealthReplay, TrueCalibrationIsOkOnBoardAndWall) {
  const std::string calib = Calibration(*truth_, "truth");
  for (const char* scene : {"board", "wall"}) {
    const HealthRun run = Run(scene, calib, std::string("truth-") + scene);
    ASSERT_EQ(run.exit_code, 0) << run.output;
    EXPECT_EQ(run.report["verdict"], "ok") << scene;
    EXPECT_LE(run.report["dy_median_px"].get<double>(), 0.1) << scene;
    EXPECT_GE(run.report["matches"].get<int>(), 100) << scene;
    ASSERT_FALSE(run.published.empty());
    EXPECT_EQ(run.published.back().verdict, "ok");
    for (const auto& h : run.published) EXPECT_NE(h.verdict, "misaligned") << scene << " frame " << h.frame_id;
  }
}

TEST_F(HealthReplay, PitchedRightCameraIsMisaligned) {
  const std::string calib = Calibration(RightCameraTurned(*truth_, kPitch, 0.2), "pitch-0.2");
  for (const char* scene : {"board", "wall"}) {
    const HealthRun run = Run(scene, calib, std::string("pitch-0.2-") + scene);
    ASSERT_EQ(run.exit_code, 0) << run.output;
    EXPECT_EQ(run.report["verdict"], "misaligned") << scene;
    EXPECT_GE(run.report["dy_median_px"].get<double>(), 0.5) << scene;
  }
}

// A roll turns the rows: dy grows with x, through zero near the centre.
TEST_F(HealthReplay, RolledRightCameraIsMisalignedWithDyGrowingWithX) {
  const std::string calib = Calibration(RightCameraTurned(*truth_, kRoll, 0.3), "roll-0.3");
  const HealthRun run = Run("wall", calib, "roll-0.3-wall");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_EQ(run.report["verdict"], "misaligned");
  EXPECT_GE(run.report["dy_median_px"].get<double>(), 0.5);
  const auto& grid = run.report["grid"]["dy_px"];
  ASSERT_EQ(grid.size(), 3u);
  for (const auto& row : grid) {
    ASSERT_EQ(row.size(), 4u);
    const double first = row.front().get<double>(), last = row.back().get<double>();
    // Monotonic along x, of one sign at the two ends, and more than a pixel apart.
    for (size_t c = 1; c < row.size(); ++c) EXPECT_GT(std::abs(row[c].get<double>() - row[c - 1].get<double>()), 0.2);
    const double step = row[1].get<double>() - row[0].get<double>();
    for (size_t c = 1; c < row.size(); ++c)
      EXPECT_GT((row[c].get<double>() - row[c - 1].get<double>()) * step, 0) << "dy is not monotonic in x: " << row;
    EXPECT_LT(first * last, 0) << row;
    EXPECT_GT(std::abs(last - first), 1.0) << row;
  }
}

TEST_F(HealthReplay, RefineRepairsAPitchedCalibration) {
  const std::string calib = Calibration(RightCameraTurned(*truth_, kPitch, 0.2), "refine-pitch-0.2");
  const std::string refined = *dir_ + "/refined-pitch-0.2.yaml";
  const HealthRun run = Run("wall", calib, "refine-pitch-0.2-wall", {"--refine", "--out", refined});
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto& r = run.report["refine"];
  ASSERT_TRUE(r["applied"].get<bool>()) << r;
  EXPECT_GE(r["dy_median_before_px"].get<double>(), 0.5);
  EXPECT_LE(r["dy_median_after_px"].get<double>(), 0.15);

  const ws::Rig rig = ws::StereoRigFromFile(refined);
  const double error_deg = RotationAngleDeg(rig.R, truth_->R);
  std::printf("[ health ] refined R is %.4f deg from the truth (the calibration was 0.2 deg off); "
              "T's direction %.4f deg\n",
              error_deg, std::acos(std::min(1.0, rig.T.normalized().dot(truth_->T.normalized()))) * 180 / M_PI);
  EXPECT_LE(error_deg, 0.02);
  EXPECT_NEAR(rig.T.norm(), truth_->T.norm(), 1e-12) << "the baseline's length is kept";
  EXPECT_NE(ReadFileText(refined).find("stereo-health refined R"), std::string::npos) << "the note";
  // The corrected calibration also went out on STEREO_CALIBRATION.
  EXPECT_EQ(Messages<widestereo::stereo_calibration_t>(ReadLog(run.out_log), ws::channel::kStereoCalibration).size(),
            1u);

  // Measured again through the refined calibration's own rectification.
  const HealthRun again = Run("wall", refined, "refined-pitch-0.2-wall");
  ASSERT_EQ(again.exit_code, 0) << again.output;
  EXPECT_EQ(again.report["verdict"], "ok");
  EXPECT_LE(again.report["dy_median_px"].get<double>(), 0.15);
}

TEST_F(HealthReplay, CorrectionBeyondTheBoundIsRefused) {
  const std::string calib = Calibration(RightCameraTurned(*truth_, kPitch, 1.0), "pitch-1.0");
  const std::string refined = *dir_ + "/refused.yaml";
  const HealthRun run = Run("wall", calib, "refuse-pitch-1.0-wall",
                            {"--refine", "--out", refined, "--max-correction-deg", "0.5"});
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_NE(run.output.find("is larger than 0.500 deg"), std::string::npos) << run.output;
  EXPECT_FALSE(run.report["refine"]["applied"].get<bool>());
  EXPECT_GT(run.report["refine"]["rotation_change_deg"].get<double>(), 0.9);
  EXPECT_EQ(ReadFileText(refined), "") << "nothing written";
  EXPECT_TRUE(Messages<widestereo::stereo_calibration_t>(ReadLog(run.out_log), ws::channel::kStereoCalibration).empty());
}

}  // namespace

namespace {

// A replay is a batch filter: the same log gives the same messages, byte for byte.
TEST_F(HealthReplay, SameLogGivesTheSameHealthMessages) {
  const std::string calib = Calibration(RightCameraTurned(*truth_, kRoll, 0.3), "replay-roll-0.3");
  std::vector<std::vector<uint8_t>> payloads[2];
  for (int run = 0; run < 2; ++run) {
    const HealthRun r = Run("wall", calib, "replay-" + std::to_string(run), {"--refine"});
    ASSERT_EQ(r.exit_code, 0) << r.output;
    for (const auto& e : ReadLog(r.out_log))
      if (e.channel == ws::channel::kCalibrationHealth || e.channel == ws::channel::kStereoCalibration)
        payloads[run].push_back(e.data);
  }
  EXPECT_EQ(payloads[0].size(), 4u) << "three CALIBRATION_HEALTH and the refined STEREO_CALIBRATION";
  EXPECT_EQ(payloads[0], payloads[1]);
}

}  // namespace
