#include "rectify/match_node.h"

#include <chrono>
#include <stdexcept>

#include "lcm_io/channels.h"
#include "lcm_io/image_codec.h"

namespace ws {

MatchResult MatchFrame(const Rectification& rect, DisparityMatcher& matcher, const CloudSampling& sampling,
                       const widestereo::stereo_frame_t& frame,
                       const std::string& calibration_source) {
  const cv::Mat left = ImageToMat(frame.left), right = ImageToMat(frame.right);
  if (left.size() != rect.input_size || right.size() != rect.input_size)
    throw std::invalid_argument(
        "frame " + std::to_string(frame.frame_id) + " is " + std::to_string(left.cols) + "x" +
        std::to_string(left.rows) + " but " + calibration_source + " is for " +
        std::to_string(rect.input_size.width) + "x" + std::to_string(rect.input_size.height));
  cv::Mat left_rect, right_rect;
  RectifyPair(rect, left, right, &left_rect, &right_rect);
  const cv::Mat disparity = matcher.Compute(left_rect, right_rect);

  MatchResult result;
  auto& d = result.disparity;
  d.utime = frame.utime;
  d.frame_id = frame.frame_id;
  d.disparity = MatToImage(disparity, frame.utime);
  d.min_disparity = float(matcher.config().min_disparity);
  d.num_disparities = matcher.config().num_disparities;
  for (int i = 0; i < 16; ++i) d.Q[i] = rect.Q.val[i];
  result.cloud = DisparityToCloud(rect, disparity, d.min_disparity, left_rect, sampling);
  result.cloud.utime = frame.utime;
  result.cloud.frame_id = frame.frame_id;
  return result;
}

MatchNode::MatchNode(Process& process, MatchConfig config)
    : process_(process), config_(std::move(config)), matcher_(config_.matcher) {
  process_.SetState("waiting for calibration");
}

void MatchNode::SetRig(const StereoRig& rig, const std::string& source) {
  const auto start = std::chrono::steady_clock::now();
  rect_ = BuildRectification(rig, config_.rectify);
  calibration_source_ = source;
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  process_.log().Info("rectification maps for " + source + " built in " + std::to_string(int(ms)) + " ms: f = " +
                      std::to_string(rect_->f) + " px, baseline = " +
                      std::to_string(rect_->baseline) + " m, " + rig.left.distortion.kind + " model");
  process_.SetState("matching");
}

void MatchNode::OnCalibration(const widestereo::stereo_calibration_t& msg) {
  SetRig(StereoRigFromMessage(msg), "the STEREO_CALIBRATION of utime " + std::to_string(msg.utime));
}

void MatchNode::OnFrame(const widestereo::stereo_frame_t& frame) {
  if (!rect_) {
    if (frames_without_calibration_++ == 0)
      process_.ReportError("frames arrive before any calibration: dropped until one does");
    process_.Counters(channel::kStereoImages).dropped++;
    return;
  }
  const MatchResult result = MatchFrame(*rect_, matcher_, config_.cloud, frame, calibration_source_);
  process_.Publish(channel::kStereoDisparity, result.disparity);
  process_.Publish(channel::kStereoCloud, result.cloud);
}

}  // namespace ws
