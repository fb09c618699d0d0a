#include "health_fixtures.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "lcm_io/channels.h"
#include "test_support.h"

namespace ws::test {

Rig RightCameraTurned(const Rig& rig, const Eigen::Vector3d& axis, double deg) {
  const Eigen::Matrix3d Q = Eigen::AngleAxisd(deg * M_PI / 180, axis.normalized()).toRotationMatrix();
  Rig turned = rig;
  turned.R = Q * rig.R;
  turned.T = Q * rig.T;
  return turned;
}

double RotationAngleDeg(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return Eigen::AngleAxisd(a * b.transpose()).angle() * 180 / M_PI;
}

void RenderScene(const std::string& config, int frames, const std::string& dir, const std::string& name) {
  const auto r = RunCommand({"stereo-capture", "--source", "sim:" + config + "?truth=" + dir + "/" + name +
                             ".truth.yaml", "--count", std::to_string(frames), "--rate", "10", "--frame-clock",
                             "--log-dir", dir, "--quiet", "--out-url", "file://" + dir + "/" + name + ".lcmlog?mode=w"},
                            120);
  ASSERT_EQ(r.exit_code, 0) << r.output;
}

HealthRun RunHealth(const std::string& dir, const std::string& images_log, const std::string& calib,
                    const std::string& name, std::vector<std::string> args) {
  HealthRun run;
  const std::string report = dir + "/" + name + ".json";
  run.out_log = dir + "/" + name + ".health.lcmlog";
  std::vector<std::string> argv = {"stereo-health", "--config", "config/stereo-health.yaml", "--period", "0",
                                   "--log-dir", dir, "--calib", calib, "--report", report, "--in-url",
                                   "file://" + images_log + "?speed=0", "--out-url", "file://" + run.out_log + "?mode=w"};
  argv.insert(argv.end(), args.begin(), args.end());
  const auto r = RunCommand(argv, 120);
  run.exit_code = r.exit_code;
  run.output = r.output;
  const std::string text = ReadFileText(report);
  if (!text.empty()) run.report = nlohmann::json::parse(text);
  run.published = Messages<widestereo::calibration_health_t>(ReadLog(run.out_log), channel::kCalibrationHealth);
  return run;
}

}  // namespace ws::test
