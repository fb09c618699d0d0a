// stereo-match's work: keeps the rectification of the newest calibration,
// and turns each stereo frame into a disparity image and a point cloud.
#pragma once

#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <string>

#include "lcm_io/image_codec.h"
#include "match/downstream_gate.h"
#include "match/matcher.h"
#include "match/frame_image_writer.h"
#include "rectify/disparity_cloud.h"
#include "rectify/rectification.h"
#include "runtime/latency_budget.h"
#include "runtime/newest_first.h"
#include "runtime/process.h"
#include "widestereo/cloud_stats_t.hpp"
#include "widestereo/disparity_t.hpp"
#include "widestereo/stereo_frame_t.hpp"

namespace ws {

struct MatchConfig {
  int64_t max_image_pixels = kDefaultMaxImagePixels;  // a larger calibration is refused
  MatcherConfig matcher;
  RectifyOptions rectify;
  CloudSampling cloud;
  ImageSaveConfig save_rectified;  // left_/right_NNNNNN.png
  ImageSaveConfig save_disparity;  // disparity_NNNNNN.png, in colour with its legend
  // Live, milliseconds from a pair's capture to its filtered cloud (its
  // CLOUD_STATS; without a filter, to its cloud): 0, no bound.
  double latency_budget_ms = 0;
};

struct MatchResult {
  widestereo::disparity_t disparity;
  PointCloud cloud;
};

// A frame rectified and matched: the first stage of MatchFrame.
struct MatchedFrame {
  std::shared_ptr<const Rectification> rect;
  int64_t utime = 0;
  int64_t frame_id = 0;
  cv::Mat disparity, left_rect, right_rect;
};

// Rectifies and matches one frame. Throws std::invalid_argument when the
// frame's size is not the calibration's (before decoding it); the message
// names the calibration by `calibration_source` (e.g. its file). With
// `times`, its stages are timed there as "decode" (the payloads: a view of a
// raw image, a decode of a compressed one), "rectify" and "match", the last
// two with the process's CPU time over them (StageTimer::Cpu::process).
MatchedFrame RectifyAndMatch(std::shared_ptr<const Rectification> rect, DisparityMatcher& matcher,
                             const widestereo::stereo_frame_t& frame,
                             const std::string& calibration_source = "the calibration",
                             StageTimes* times = nullptr);
// The second stage: the disparity message and the cloud, sampled as
// `sampling` says.
MatchResult ToMessages(const MatchedFrame& matched, const MatcherConfig& matcher,
                       const CloudSampling& sampling);
// Both stages, one after the other.
MatchResult MatchFrame(const Rectification& rect, DisparityMatcher& matcher, const CloudSampling& sampling,
                       const widestereo::stereo_frame_t& frame,
                       const std::string& calibration_source = "the calibration");

// Wires MatchFrame to the bus: a calibration file given at the start, and
// every STEREO_CALIBRATION after it, replaces the calibration, checked on its
// numbers first (calibration_size.h: one larger than config.max_image_pixels
// is refused, the one before kept); frames of another size are rejected
// before they are decoded. Its maps are built as it arrives, not at its first
// frame: live on a thread of their own (the newest calibration waiting is
// built next, one replaced before its build started is not built), so that
// neither the input thread nor matching stops for them (about 0.2 s for
// 1280x960). Meanwhile frames go on through the maps of the calibration
// before when it is for the same image size (each disparity carries the
// geometry it was matched with); without one (the first calibration, or
// another size) a frame waits for the new maps in the matching stage, and
// the frames after it are skipped and counted as below. From a log they are
// built in line, before the next message: every frame after a calibration
// is matched through it. STEREO_IMAGES
// become STEREO_DISPARITY and STEREO_CLOUD, and the rectified pairs PNG
// files and the disparity as a colour PNG with its legend in metres when
// config.save_rectified and save_disparity say so (frame_image_writer.h).
// The maps rectify straight to the matcher's resolution
// (RectifyOptions::downscale = MatcherConfig::downscale): the rectified
// pairs, the disparity (with its f, cx, cy and Q) and the cloud are all on
// that grid.
//
// Live, the work runs as a small pipeline (runtime/newest_first.h) on two
// threads of their own, so that the input thread only hands frames over:
// matching takes the newest frame waiting (a frame replaced before it was
// taken is counted as skipped on STEREO_IMAGES) and rectifies it, matches it
// and builds its cloud, while the messages of the frame before are encoded
// and sent. The three stages that spread over every core are on one thread:
// OpenCV runs one parallel loop of a process at a time on every core, and
// one started meanwhile on another thread runs on that thread alone (a
// matching begun while the cloud before was built ran on one core, twice as
// long, with the other free). At most one frame waits for each stage.
// Live, a pair is also skipped, whole and before it is matched, when the
// cloud filter downstream would still have one cloud being filtered and
// another waiting by the time its cloud came (match/downstream_gate.h: its
// CLOUD_STATS acknowledge them), instead of being matched for a cloud that
// would replace the waiting one unfiltered; and with config.latency_budget_ms,
// when its age plus the median time from a matching's start to the filter's
// acknowledgement would exceed it (runtime/latency_budget.h): matched, its
// cloud would come too late to use, and its matching would delay the next.
// Every frame from the first received is thus published, counted as skipped
// (each skip with its reason: Process::CountSkipped), dropped (a frame-id
// gap), or rejected. From a log, both stages run in line: nothing is dropped
// or skipped, and every replay gives the same output.
class MatchNode {
 public:
  MatchNode(Process& process, MatchConfig config);
  ~MatchNode();
  // Uses the rig from now on and has its maps built (above); `source` names
  // the calibration in log lines and errors ("calibration file calib.yaml",
  // "STEREO_CALIBRATION"). Throws std::invalid_argument for a rig larger
  // than config.max_image_pixels, keeping the one before.
  void SetRig(const Rig& rig, const std::string& source);
  void OnCalibration(const widestereo::stereo_calibration_t& msg);
  // The cloud filter's acknowledgement of a cloud (live only; ignored from
  // a log).
  void OnCloudStats(const widestereo::cloud_stats_t& stats);
  // Takes the frame's payload (moves it into the pipeline). Live, a frame
  // that comes while no maps can serve it (the first calibration's, or one
  // for a new image size, still being built) is skipped, not held: held,
  // it would be matched a build's time late, and its cloud stale.
  void OnFrame(widestereo::stereo_frame_t& frame);
  // Returns when every frame handed over has been published or counted, and
  // the maps of the calibrations handed over are built.
  void Drain();
  // True once the maps of the rig in use are built, waiting at most `timeout`
  // for them; false without a rig, when their build failed, or on timeout.
  bool WaitForMaps(std::chrono::milliseconds timeout);

 private:
  // A calibration whose maps are to be built.
  struct MapsJob {
    std::shared_ptr<const Rig> rig;
    std::shared_ptr<const Rectification> geometry;  // without maps
    std::string source;
  };
  void BuildMaps(MapsJob& job);
  void Match(widestereo::stereo_frame_t& frame);
  // The rectification to match a frame through, with its maps, and its
  // name: the rig in use's, or while its maps are being built the one before
  // if it is for the same image size; otherwise it waits for them. Throws
  // std::invalid_argument for a frame of another size than the rig in use's,
  // std::runtime_error when its maps could not be built.
  std::shared_ptr<const Rectification> Maps(const widestereo::stereo_frame_t& frame, std::string* source);
  // A frame matched and its messages built: what the publishing stage sends
  // (and saves).
  struct Outgoing {
    MatchedFrame matched;
    MatchResult messages;
  };
  void Publish(Outgoing& outgoing);

  Process& process_;
  MatchConfig config_;
  FrameImageWriter rectified_writer_;  // used by the publishing stage only
  FrameImageWriter disparity_writer_;  // likewise
  // At the matcher's resolution (AtMatchScale), as the rectification:
  // used by the matching stage only, but for its const config().
  DisparityMatcher matcher_;
  // Guards rig_, rect_, rect_has_maps_, maps_error_, calibration_source_,
  // ready_ and ready_source_.
  std::mutex rect_mutex_;
  // Notified (under rect_mutex_) when the rig in use changes or its maps
  // are built or fail.
  std::condition_variable maps_changed_;
  std::shared_ptr<const Rig> rig_;  // the calibration in use
  // Its rectification: without maps until they are built.
  std::shared_ptr<const Rectification> rect_;
  bool rect_has_maps_ = false;
  std::string maps_error_;  // why its maps could not be built ("" : they are, or will be)
  std::string calibration_source_;
  // The newest rectification with maps, and its calibration's name: rect_
  // once its maps are built, until then the one before (none at first).
  std::shared_ptr<const Rectification> ready_;
  std::string ready_source_;
  int64_t frames_without_calibration_ = 0;
  DownstreamGate downstream_;
  LatencyBudget budget_;  // used by the matching stage only
  // Builds the maps of the newest calibration. Declared before the stages:
  // destroyed after them, since matching may wait for it.
  NewestFirst<MapsJob> maps_;
  // Destroyed (drained) before the rest, matching before publishing.
  NewestFirst<Outgoing> publish_;
  NewestFirst<widestereo::stereo_frame_t> match_;
};

}  // namespace ws
