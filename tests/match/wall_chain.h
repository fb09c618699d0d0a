// The flat-wall chain as processes over file:// logs, for the wall tests:
// stereo-capture renders a simulator wall scene, stereo-match with a
// calibration file of a rig, then stereo-cloud; each frame measured against
// the simulator's truth (wall_analysis.h).
#pragma once

#include <string>
#include <vector>

#include "rig/rig.h"
#include "sim/ground_truth.h"
#include "wall_analysis.h"

namespace ws::test {

// stereo-capture --source sim:CONFIG --count frames into DIR/images.lcmlog;
// the simulator's truth.
SimTruth CaptureWall(const std::string& dir, const std::string& config, int frames);

struct WallRun {
  std::vector<DisparityErrors> disparity;  // per frame
  std::vector<WallFit> wall;               // per frame
};

struct WallChainOptions {
  std::vector<std::string> match_args;  // stereo-match options after these
  std::vector<std::string> cloud_args;  // stereo-cloud options after --config
  std::string match_config = "config/stereo-match.yaml";
  std::string cloud_config = "config/stereo-cloud.yaml";
  double focal_scale = 1.0;  // stereo-match's --focal-scale, and the truth's rectification
  RectificationMode mode = RectificationMode::kAuto;  // --rectification, the same for the truth
};

struct ChainLogs {
  std::string match;  // stereo-match's output: STEREO_DISPARITY, STEREO_CLOUD
  std::string cloud;  // stereo-cloud's: STEREO_CLOUD_FILTERED, CLOUD_STATS
};

// stereo-match --config --calib (the rig written as DIR/NAME.yaml)
// --num-disparities --focal-scale --rectification [match_args] on
// DIR/images.lcmlog into DIR/NAME-match.lcmlog, then stereo-cloud --config
// [cloud_args] into DIR/NAME-cloud.lcmlog.
ChainLogs RunMatchAndCloud(const std::string& dir, const Rig& rig, const std::string& name,
                           const std::string& num_disparities, const WallChainOptions& options);

// RunMatchAndCloud, then every frame's disparity and wall against the truth
// seen through the true rig's rectification of the same focal scale
// (printed).
WallRun RunWallChain(const std::string& dir, const SimTruth& truth, const Rig& rig,
                     const std::string& name, int frames, const std::string& num_disparities,
                     const WallChainOptions& options = {});

}  // namespace ws::test
