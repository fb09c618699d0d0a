#include "match_fixtures.h"

#include <yaml-cpp/yaml.h>

#include <fstream>

#include "sim/sim_config.h"
#include "test_support.h"

namespace ws::test {
namespace {

widestereo::camera_calibration_t Pinhole(const std::string& name, int width, int height, double f) {
  widestereo::camera_calibration_t c{};
  c.name = name;
  c.image_width = width;
  c.image_height = height;
  c.model = "poly6";
  c.coeffs = {0, 0, 0};
  c.ncoeffs = 3;
  c.fx = c.fy = f;
  c.cx = (width - 1) / 2.0;
  c.cy = (height - 1) / 2.0;
  return c;
}

}  // namespace

widestereo::stereo_calibration_t IdentityCalibration(int width, int height, double f,
                                                     double baseline) {
  widestereo::stereo_calibration_t calib{};
  calib.left = Pinhole("left", width, height, f);
  calib.right = Pinhole("right", width, height, f);
  calib.R[0] = calib.R[4] = calib.R[8] = 1;
  calib.T[0] = -baseline;
  return calib;
}

Rig RigFittedAs(const Rig& rig, const std::string& kind) {
  const SimConfig theia = ParseSimConfig(
      "rig: {baseline: 0.3, left: {lens: theia, fit: " + kind + "}}\nscene: {wall: {frames: 1}}\n",
      "the Theia-like lens fitted as " + kind, ".");
  Rig fitted = rig;
  fitted.left.distortion = fitted.right.distortion = theia.left.distortion;
  return fitted;
}

std::string FisheyeSceneConfig(const std::string& dir, const std::string& scene) {
  YAML::Node config = YAML::LoadFile(SourceDir() + "/config/sim/fisheye.yaml");
  const YAML::Node kept = YAML::Clone(config["scene"][scene]);
  config["scene"] = YAML::Node(YAML::NodeType::Map);
  config["scene"][scene] = kept;
  const std::string path = dir + "/fisheye-" + scene + ".yaml";
  std::ofstream(path) << config;
  return path;
}

}  // namespace ws::test
