#include "match/match_node.h"

#include <chrono>
#include <limits>
#include <optional>
#include <stdexcept>

#include "lcm_io/channels.h"
#include "lcm_io/image_codec.h"
#include "match/match_region.h"
#include "rectify/calibration_size.h"
#include "rig/rig_message.h"
#include "runtime/wall_clock.h"
#include "view/disparity_colour.h"

namespace ws {

MatchedFrame RectifyAndMatch(std::shared_ptr<const Rectification> rect, DisparityMatcher& matcher,
                             const widestereo::stereo_frame_t& frame,
                             const std::string& calibration_source, StageTimes* times) {
  RequireFrameSize(frame, rect->input_size, calibration_source);
  std::optional<StageTimer> decode;
  if (times) decode.emplace(*times, "decode");
  // Views of the frame's payloads (it outlives the remap): no copy of a raw
  // image, a decode of a compressed one.
  const cv::Mat left = ImageView(frame.left), right = ImageView(frame.right);
  decode.reset();
  std::optional<StageTimer> rectify;
  if (times) rectify.emplace(*times, "rectify", StageTimer::Cpu::process);
  MatchedFrame matched;
  const cv::Rect region = MatchRegion(*rect, matcher.config());
  RectifyPair(*rect, left, right, &matched.left_rect, &matched.right_rect, region);
  rectify.reset();
  std::optional<StageTimer> match;
  if (times) match.emplace(*times, "match", StageTimer::Cpu::process);
  matched.disparity = cv::Mat(rect->size, CV_32F, cv::Scalar(matcher.config().min_disparity - 1));
  cv::Mat in_region = matched.disparity(region);  // matched straight into the whole image's
  matcher.ComputeInto(matched.left_rect(region), matched.right_rect(region), &in_region,
                      ContextColumns(*rect, region));
  // No disparity where either rectified image holds no image (outside a
  // lens's field or its input image): the matcher saw the constant border.
  matched.disparity.setTo(-std::numeric_limits<float>::infinity(), rect->no_image);
  matched.rect = std::move(rect);
  matched.utime = frame.utime;
  matched.frame_id = frame.frame_id;
  return matched;
}

MatchResult ToMessages(const MatchedFrame& matched, const MatcherConfig& matcher,
                       const CloudSampling& sampling) {
  const Rectification& rect = *matched.rect;
  MatchResult result;
  auto& d = result.disparity;
  d.utime = matched.utime;
  d.frame_id = matched.frame_id;
  d.disparity = MatToImage(matched.disparity, matched.utime);
  d.min_disparity = float(matcher.min_disparity);
  d.num_disparities = matcher.num_disparities;
  for (int i = 0; i < 16; ++i) d.Q[i] = rect.Q.val[i];
  d.rectification = rect.mode == RectificationMode::kLatLon ? widestereo::disparity_t::RECTIFICATION_LATLON
                                                             : widestereo::disparity_t::RECTIFICATION_PINHOLE;
  d.f = rect.f;
  d.cx = rect.cx;
  d.cy = rect.cy;
  d.baseline = rect.baseline;
  result.cloud = DisparityToCloud(rect, matched.disparity, d.min_disparity, matched.left_rect, sampling);
  result.cloud.utime = matched.utime;
  result.cloud.frame_id = matched.frame_id;
  return result;
}

MatchResult MatchFrame(const Rectification& rect, DisparityMatcher& matcher, const CloudSampling& sampling,
                       const widestereo::stereo_frame_t& frame,
                       const std::string& calibration_source) {
  // Not owned: the shared pointer lives only as long as this call.
  std::shared_ptr<const Rectification> view(&rect, [](const Rectification*) {});
  return ToMessages(RectifyAndMatch(view, matcher, frame, calibration_source), matcher.config(), sampling);
}

namespace {

template <class T>
typename NewestFirst<T>::Policy Live(const Process& process, typename NewestFirst<T>::Policy policy) {
  return process.file_input() ? NewestFirst<T>::Policy::in_line : policy;
}

}  // namespace

MatchNode::MatchNode(Process& process, MatchConfig config)
    : process_(process),
      config_(std::move(config)),
      rectified_writer_(config_.save_rectified, "--save-rectified"),
      disparity_writer_(config_.save_disparity, "--save-disparity"),
      matcher_(AtMatchScale(config_.matcher)),
      budget_(config_.latency_budget_ms),
      maps_(Live<MapsJob>(process, NewestFirst<MapsJob>::Policy::newest), [this](MapsJob& job) { BuildMaps(job); },
            [this](const MapsJob& job) {
              process_.log().Info("maps for " + job.source + " not built: a newer calibration replaced it");
            }),
      publish_(Live<Outgoing>(process, NewestFirst<Outgoing>::Policy::wait),
               [this](Outgoing& outgoing) { Publish(outgoing); }),
      match_(Live<widestereo::stereo_frame_t>(process, NewestFirst<widestereo::stereo_frame_t>::Policy::newest),
             [this](widestereo::stereo_frame_t& frame) { Match(frame); },
             [this](const widestereo::stereo_frame_t&) {
               process_.CountSkipped(channel::kStereoImages, "a newer pair came while matching");
             }) {
  process_.SetState("waiting for calibration");
  process_.AtExit([this] { Drain(); });
}

MatchNode::~MatchNode() { Drain(); }

void MatchNode::SetRig(const Rig& rig, const std::string& source) {
  RectifyOptions options = config_.rectify;
  options.downscale = config_.matcher.downscale;  // straight to the matcher's resolution
  auto geometry = std::make_shared<const Rectification>(
      CalibrationGeometry(rig, options, config_.max_image_pixels, source));
  const cv::Size size = geometry->input_size;
  MapsJob job{std::make_shared<const Rig>(rig), geometry, source};
  {
    std::lock_guard<std::mutex> lock(rect_mutex_);
    rig_ = job.rig;
    rect_ = std::move(geometry);
    rect_has_maps_ = false;
    maps_error_.clear();
    calibration_source_ = source;
  }
  maps_changed_.notify_all();  // a frame waiting for the maps before waits for these now
  process_.log().Info("using " + source + " (" + std::to_string(size.width) + "x" + std::to_string(size.height) +
                      ", " + ModelName(rig.left.distortion.kind) + " model); building its maps");
  process_.SetState("matching");
  maps_.Offer(std::move(job));
}

void MatchNode::BuildMaps(MapsJob& job) {
  {
    std::lock_guard<std::mutex> lock(rect_mutex_);
    if (rig_ != job.rig) return;  // replaced while it waited: the newer one is built next
  }
  try {
    const auto start = std::chrono::steady_clock::now();
    Rectification rect = *job.geometry;
    BuildRectificationMaps(*job.rig, &rect);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    const cv::Rect region = MatchRegion(rect, matcher_.config());
    process_.log().Info("rectification maps for " + job.source + " built in " + std::to_string(int(ms)) + " ms: f = " +
                        std::to_string(rect.f) + " px, " + RectificationModeName(rect.mode) + " rectification at " +
                        std::to_string(rect.size.width) + "x" + std::to_string(rect.size.height) + ", baseline = " +
                        std::to_string(rect.baseline) + " m, " + ModelName(job.rig->left.distortion.kind) +
                        " model; matching " + std::to_string(region.width) + "x" + std::to_string(region.height) +
                        " of it (match/match_region.h)");
    auto built = std::make_shared<const Rectification>(std::move(rect));
    std::lock_guard<std::mutex> lock(rect_mutex_);
    if (rig_ == job.rig) {  // not replaced meanwhile
      rect_ = ready_ = std::move(built);
      rect_has_maps_ = true;
      ready_source_ = job.source;
    }
  } catch (const std::exception& e) {
    const std::string error = "the rectification maps for " + job.source + " could not be built: " + e.what();
    {
      std::lock_guard<std::mutex> lock(rect_mutex_);
      if (rig_ == job.rig) maps_error_ = error;
    }
    process_.ReportError(error);
  }
  maps_changed_.notify_all();
}

std::shared_ptr<const Rectification> MatchNode::Maps(const widestereo::stereo_frame_t& frame, std::string* source) {
  std::unique_lock<std::mutex> lock(rect_mutex_);
  while (true) {
    *source = calibration_source_;
    RequireFrameSize(frame, rect_->input_size, calibration_source_);
    if (rect_has_maps_) return rect_;
    if (!maps_error_.empty()) throw std::runtime_error(maps_error_);
    // Being built (from a log they were built in line: never here): the
    // calibration before for this size meanwhile, or wait. A newer
    // calibration while waiting: its size is checked again.
    if (ready_ && ready_->input_size == rect_->input_size) {
      *source = ready_source_;
      return ready_;
    }
    const std::shared_ptr<const Rig> rig = rig_;
    maps_changed_.wait(lock, [&] { return rig_ != rig || rect_has_maps_ || !maps_error_.empty(); });
  }
}

bool MatchNode::WaitForMaps(std::chrono::milliseconds timeout) {
  std::unique_lock<std::mutex> lock(rect_mutex_);
  maps_changed_.wait_for(lock, timeout, [&] { return rig_ && (rect_has_maps_ || !maps_error_.empty()); });
  return rig_ && rect_has_maps_;
}

void MatchNode::OnCalibration(const widestereo::stereo_calibration_t& msg) {
  SetRig(RigFromMessage(msg), "the STEREO_CALIBRATION of utime " + std::to_string(msg.utime));
}

void MatchNode::OnFrame(widestereo::stereo_frame_t& frame) {
  bool calibrated, servable;
  {
    std::lock_guard<std::mutex> lock(rect_mutex_);
    calibrated = rig_ != nullptr;
    // Maps to match it through now (or an error to report): the rig's, or
    // the ones before for the same image size.
    servable = rect_has_maps_ || !maps_error_.empty() || (ready_ && ready_->input_size == rect_->input_size);
  }
  if (!calibrated) {
    if (frames_without_calibration_++ == 0)
      process_.ReportError("frames arrive before any calibration: dropped until one does");
    process_.Counters(channel::kStereoImages).dropped++;
    return;
  }
  if (!servable) {  // live, the first maps for this size being built: it would be stale once they are
    process_.CountSkipped(channel::kStereoImages, "came while the first maps were built");
    return;
  }
  match_.Offer(std::move(frame));
}

void MatchNode::Drain() {
  match_.Drain();
  publish_.Drain();
  maps_.Drain();
}

void MatchNode::OnCloudStats(const widestereo::cloud_stats_t& stats) {
  if (!process_.file_input()) downstream_.Acknowledge(stats.frame_id, DownstreamGate::Clock::now());
}

void MatchNode::Match(widestereo::stereo_frame_t& frame) {
  // Whole, before any work is spent on it. The budget first: the gate,
  // once open, times this matching.
  if (!process_.file_input() && budget_.Late(frame.utime, WallMicros(), downstream_.ToAcknowledgement()))
    return process_.CountSkipped(channel::kStereoImages, LatencyBudget::kSkipReason);
  if (!process_.file_input() && !downstream_.Open(DownstreamGate::Clock::now()))
    return process_.CountSkipped(channel::kStereoImages, "the cloud filter had a cloud waiting");
  try {
    std::string source;
    std::shared_ptr<const Rectification> rect = Maps(frame, &source);
    Outgoing outgoing{RectifyAndMatch(std::move(rect), matcher_, frame, source, &process_.stage_times()), {}};
    StageTimer cloud(process_.stage_times(), "cloud", StageTimer::Cpu::process);
    outgoing.messages = ToMessages(outgoing.matched, matcher_.config(), config_.cloud);
    cloud.Stop();
    // On its way to the filter from now: the next pair's matching may start
    // before the publishing stage has sent this one's cloud.
    if (!process_.file_input()) downstream_.Sent(outgoing.matched.frame_id, DownstreamGate::Clock::now());
    publish_.Offer(std::move(outgoing));
  } catch (const std::exception& e) {
    process_.HandleRejected(channel::kStereoImages, e.what());
  }
}

void MatchNode::Publish(Outgoing& outgoing) {
  const MatchedFrame& matched = outgoing.matched;
  // Its range and geometry name the legend's metres.
  const widestereo::disparity_t& disparity = outgoing.messages.disparity;
  try {
    process_.Publish(channel::kStereoDisparity, disparity);
    process_.Publish(channel::kStereoCloud, outgoing.messages.cloud);
  } catch (const std::exception& e) {
    process_.HandleRejected(channel::kStereoImages, e.what());
  }
  try {
    if (rectified_writer_.Wants(matched.frame_id))
      rectified_writer_.Write(matched.frame_id, {{"left", matched.left_rect}, {"right", matched.right_rect}});
    if (disparity_writer_.Wants(matched.frame_id)) {
      const view::DisparityLegend legend = view::MakeLegend(disparity);
      disparity_writer_.Write(matched.frame_id,
                              {{"disparity", view::WithLegend(view::ColourDisparity(ImageToMat(disparity.disparity), legend), legend)}});
    }
  } catch (const std::exception& e) {
    process_.ReportRecurring(e.what());
  }
}

}  // namespace ws
