// stereo-match's work: keeps the rectification of the newest calibration,
// and turns each stereo frame into a disparity image and a point cloud.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "rectify/disparity_cloud.h"
#include "rectify/matcher.h"
#include "rectify/rectification.h"
#include "runtime/process.h"
#include "widestereo/disparity_t.hpp"
#include "widestereo/stereo_frame_t.hpp"

namespace ws {

struct MatchConfig {
  MatcherConfig matcher;
  RectifyOptions rectify;
  CloudSampling cloud;
};

struct MatchResult {
  widestereo::disparity_t disparity;
  widestereo::point_cloud_t cloud;
};

// Rectifies and matches one frame; the cloud is sampled as `sampling` says.
// Throws std::invalid_argument when the frame's size is not the
// calibration's; the message names the calibration by `calibration_source`
// (e.g. its file).
MatchResult MatchFrame(const Rectification& rect, DisparityMatcher& matcher, const CloudSampling& sampling,
                       const widestereo::stereo_frame_t& frame,
                       const std::string& calibration_source = "the calibration");

// Wires MatchFrame to the bus: a calibration file given at the start, and
// every STEREO_CALIBRATION after it, (re)builds the maps; STEREO_IMAGES
// become STEREO_DISPARITY and STEREO_CLOUD.
class MatchNode {
 public:
  MatchNode(Process& process, MatchConfig config);
  // Builds the maps now; `source` names the calibration in log lines and
  // errors ("calibration file calib.yaml", "STEREO_CALIBRATION").
  void SetRig(const StereoRig& rig, const std::string& source);
  void OnCalibration(const widestereo::stereo_calibration_t& msg);
  void OnFrame(const widestereo::stereo_frame_t& frame);

 private:
  Process& process_;
  MatchConfig config_;
  DisparityMatcher matcher_;
  std::optional<Rectification> rect_;
  std::string calibration_source_;
  int64_t frames_without_calibration_ = 0;
};

}  // namespace ws
