// Scenes, calibrations and runs of stereo-health shared by its tests.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "rig/rig.h"
#include "widestereo/calibration_health_t.hpp"

namespace ws::test {

// The calibration with the right camera turned about its own centre by
// `deg` about its axis (x: pitch, z: roll): X_right = Q (R X_left + T).
Rig RightCameraTurned(const Rig& rig, const Eigen::Vector3d& axis, double deg);

// The angle (degrees) between two rotations.
double RotationAngleDeg(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b);

// stereo-capture --source sim:CONFIG --count N into DIR/NAME.lcmlog (truth in
// DIR/NAME.truth.yaml): the simulator's rendered frames.
void RenderScene(const std::string& config, int frames, const std::string& dir, const std::string& name);

struct HealthRun {
  int exit_code = -1;
  std::string output;
  nlohmann::json report;  // --report, null when not written
  std::vector<widestereo::calibration_health_t> published;
  std::string out_log;
};

// stereo-health --period 0 on a log with a calibration file, as a batch
// filter, with --report and more arguments.
HealthRun RunHealth(const std::string& dir, const std::string& images_log, const std::string& calib,
                    const std::string& name, std::vector<std::string> args = {});

}  // namespace ws::test
