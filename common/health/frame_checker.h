// One frame's check: a stereo pair rectified through the calibration (the
// rectification stereo-match builds, with its options), matched
// (health/rectified_matches.h), each match's dy and its rays in the two
// camera frames (for the refinement).
#pragma once

#include <vector>

#include <opencv2/core.hpp>

#include "health/dy_figures.h"
#include "health/extrinsic_refine.h"
#include "health/rectified_matches.h"
#include "rectify/rectification.h"

namespace ws {

struct FrameCheck {
  RectifiedMatches matches;
  std::vector<DyMatch> dy;
  std::vector<RayMatch> rays;
};

class FrameChecker {
 public:
  // Builds the maps; throws std::invalid_argument as BuildRectification does.
  FrameChecker(const Rig& rig, const RectifyOptions& rectify, const FeatureOptions& features);

  // `left`, `right`: the input images, grey (8 or 16 bits) or colour;
  // throws std::invalid_argument when their size is not the calibration's
  // (the message names the calibration as `source`) or their type is not usable.
  FrameCheck Check(const cv::Mat& left, const cv::Mat& right, const std::string& source) const;

  const Rectification& rect() const { return rect_; }

 private:
  Rectification rect_;
  FeatureOptions features_;
  cv::Mat filled_left_, filled_right_;
};

}  // namespace ws
