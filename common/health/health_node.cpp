#include "health/health_node.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <stdexcept>

#include "health/health_report.h"
#include "lcm_io/channels.h"
#include "lcm_io/image_codec.h"
#include "rectify/calibration_size.h"
#include "rig/publish_calibration.h"
#include "rig/rig_file.h"
#include "rig/rig_message.h"
#include "runtime/json_file.h"

namespace ws {
namespace {

std::string Fixed(double value, int digits = 3) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", digits, value);
  return text;
}

}  // namespace

HealthNode::HealthNode(Process& process, HealthConfig config)
    : process_(process),
      commands_(process.options().name, {{"refine", "refine", {}, [this](const CommandArgs&) { RefineCommand(); }}}),
      config_(std::move(config)),
      window_(config_.verdict) {
  process_.SetState("waiting for calibration");
}

void HealthNode::Start(const std::string& calib_file) {
  if (!calib_file.empty())
    SetCalibration(ReadCalibrationFile(calib_file), "calibration file " + calib_file);
  process_.Subscribe<widestereo::stereo_calibration_t>(channel::kStereoCalibration,
                                                       [this](const auto& msg) { OnCalibration(msg); });
  process_.Subscribe<widestereo::stereo_frame_t>(
      channel::kStereoImages, [this](const auto& msg) { OnFrame(msg); }, 2);
  process_.Subscribe<widestereo::command_t>(channel::kStereoCommand,
                                            [this](const auto& msg) { commands_.Dispatch(msg); });
  process_.Counters(channel::kCalibrationHealth);
  process_.AtEndOfInput([this] { AtEnd(); });
  process_.SetProgress([this] {
    return "checked " + std::to_string(frames_checked_) + " frames: " + window_.verdict() +
           (calibration_ ? "" : " (no calibration yet)");
  });
}

void HealthNode::SetCalibration(const Rig& rig, const std::string& source) {
  // A throw here changes nothing.
  calibration_size_ = CalibrationGeometry(rig, config_.rectify, config_.max_image_pixels, source).input_size;
  checker_.reset();
  calibration_ = rig;
  source_ = source;
  window_.Clear();
  kept_.clear();
  kept_count_ = 0;
  last_check_utime_ = 0;
  process_.log().Info("using " + source + " (" + std::to_string(calibration_size_.width) + "x" +
                      std::to_string(calibration_size_.height) + "); its maps are built for its first frame of that size");
  process_.SetState("checking");
}

void HealthNode::BuildChecker() {
  const auto start = std::chrono::steady_clock::now();
  checker_ = FrameChecker(*calibration_, config_.rectify, config_.features);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  const Rectification& rect = checker_->rect();
  process_.log().Info("rectification maps for " + source_ + " built in " + std::to_string(int(ms)) +
                      " ms: f = " + Fixed(rect.f, 2) + " px, " + std::to_string(rect.size.width) + "x" +
                      std::to_string(rect.size.height));
}

void HealthNode::OnCalibration(const widestereo::stereo_calibration_t& msg) {
  if (published_ && msg.utime == published_->utime && std::equal(msg.R, msg.R + 9, published_->R) &&
      std::equal(msg.T, msg.T + 3, published_->T))
    return;  // our own refinement, heard back: in use already
  SetCalibration(RigFromMessage(msg), "the STEREO_CALIBRATION of utime " + std::to_string(msg.utime));
}

void HealthNode::OnFrame(const widestereo::stereo_frame_t& frame) {
  if (!calibration_) {
    if (frames_without_calibration_++ == 0)
      process_.ReportError("frames arrive before any calibration: dropped until one does");
    process_.Counters(channel::kStereoImages).dropped++;
    return;
  }
  const int64_t period_us = int64_t(config_.period_s * 1e6);
  if (frames_checked_ > 0 && last_check_utime_ != 0 && frame.utime - last_check_utime_ < period_us &&
      frame.utime >= last_check_utime_)
    return process_.CountSkipped(channel::kStereoImages, "not due: one frame checked a period");  // message time
  Check(frame);
}

void HealthNode::Check(const widestereo::stereo_frame_t& frame) {
  RequireFrameSize(frame, calibration_size_, source_);  // before decoding it or building maps
  if (!checker_) BuildChecker();
  FrameCheck check;
  try {
    check = checker_->Check(ImageView(frame.left), ImageView(frame.right), source_);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("frame " + std::to_string(frame.frame_id) + ": " + e.what());
  }
  const RectifiedMatches& m = check.matches;
  window_.Add(check.dy, config_.grid, checker_->rect().size);
  if (window_.newest_usable()) {
    kept_count_ += check.rays.size();
    kept_.push_back(std::move(check.rays));
    while (kept_count_ > size_t(config_.max_kept_matches) && kept_.size() > 1) {
      kept_count_ -= kept_.front().size();
      kept_.pop_front();
    }
  }
  last_check_utime_ = frame.utime;
  last_frame_id_ = frame.frame_id;
  ++frames_checked_;
  const widestereo::calibration_health_t health = Health(frame.utime, frame.frame_id);
  process_.Publish(channel::kCalibrationHealth, health);
  process_.SetState(health.verdict);  // stereo-status's STATE column
  process_.log().Detail("frame " + std::to_string(frame.frame_id) + ": corners " + std::to_string(m.corners_left) +
                        "/" + std::to_string(m.corners_right) + ", candidates " + std::to_string(m.candidates) +
                        ", tracked " + std::to_string(m.refined) + ", inliers " + std::to_string(m.left.size()) +
                        "; window: median |dy| " + Fixed(health.dy_median_px) + " px, " + health.verdict);
}

widestereo::calibration_health_t HealthNode::Health(int64_t utime, int64_t frame_id) const {
  const DyFigures f = ComputeDyFigures(window_.Matches(), checker_ ? checker_->rect().size : cv::Size(1, 1), config_.grid);
  widestereo::calibration_health_t h{};
  h.utime = utime;
  h.frame_id = frame_id;
  h.verdict = window_.verdict();
  h.max_dy_px = config_.verdict.max_dy;
  h.dy_median_px = f.median_abs;
  h.dy_p95_px = f.p95_abs;
  h.matches = f.matches;
  h.frames = window_.usable_frames();
  h.grid_rows = config_.grid.rows;
  h.grid_cols = config_.grid.cols;
  h.grid_dy_px = f.region_dy;
  h.grid_matches = f.region_matches;
  h.calibration = source_;
  return h;
}

RefineResult HealthNode::Refine() {
  if (!calibration_) throw std::runtime_error("refine: no calibration yet");
  if (!checker_) throw std::runtime_error("refine: no frame checked with " + source_ + " yet");
  std::vector<RayMatch> matches;
  for (const auto& frame : kept_) matches.insert(matches.end(), frame.begin(), frame.end());
  RefineResult r = RefineExtrinsics(*calibration_, checker_->rect().f, matches, checker_->rect().size, config_.grid,
                                    config_.refine);
  last_refine_ = r;
  const std::string figures = "median |dy| " + Fixed(r.dy_median_before) + " -> " + Fixed(r.dy_median_after) +
                              " px, 95th percentile " + Fixed(r.dy_p95_before) + " -> " + Fixed(r.dy_p95_after) +
                              " px over " + std::to_string(r.matches) + " matches; R changed by " +
                              Fixed(r.rotation_change_deg, 4) + " deg, T's direction by " +
                              Fixed(r.translation_direction_change_deg, 4) + " deg";
  if (!r.applied) {
    process_.ReportError("refinement refused: " + r.refused + " (" + figures + ")");
    return r;
  }
  process_.log().Info("refined the extrinsics of " + source_ + ": " + figures);
  Rig refined = *calibration_;
  refined.R = r.rig.R;
  refined.T = r.rig.T;
  refined.note = "stereo-health refined R and the direction of T (its length kept; intrinsics and distortion "
                 "of " + source_ + " unchanged) from " + std::to_string(r.matches) + " matches in " +
                 std::to_string(kept_.size()) + " frames: median |dy| " + Fixed(r.dy_median_before) + " -> " +
                 Fixed(r.dy_median_after) + " px";
  published_ = MessageFromRig(refined, process_.Now());
  PublishCalibration(process_, *published_);
  if (!config_.out_yaml.empty()) {
    WriteCalibrationFile(config_.out_yaml, refined);
    process_.log().Info("wrote " + config_.out_yaml);
  }
  SetCalibration(refined, "the refined " + source_);
  return r;
}

void HealthNode::RefineCommand() {
  const RefineResult r = Refine();
  if (!r.applied) throw std::runtime_error("refine refused: " + r.refused);
}

void HealthNode::AtEnd() {
  const widestereo::calibration_health_t health = Health(process_.Now(), last_frame_id_);
  const bool refused = config_.refine_at_end && !Refine().applied;
  if (!config_.report_json.empty()) {
    WriteJsonFile(config_.report_json, HealthReport(health, frames_checked_, last_refine_));
    process_.log().Info("wrote " + config_.report_json);
  }
  if (refused) process_.Fatal("no refinement from the frames of the log: " + last_refine_->refused);
  process_.log().Info("verdict " + health.verdict + ": median |dy| " + Fixed(health.dy_median_px) +
                      " px, 95th percentile " + Fixed(health.dy_p95_px) + " px, " + std::to_string(health.matches) +
                      " matches in " + std::to_string(health.frames) + " frames");
}

}  // namespace ws
