// stereo-health's work on a ws::Process:
//
//  - the calibration: --calib FILE at the start, then every
//    STEREO_CALIBRATION (each one replaces the maps with the rectification
//    stereo-match uses, built for its first frame of its image size, and
//    forgets the matches of the one before); one larger than
//    max_image_pixels is refused (rectify/calibration_size.h);
//  - STEREO_IMAGES: a frame every `period_s` of message time (0: every
//    frame; the others are counted as skipped, by design) is rectified,
//    matched (health/rectified_matches.h) and added to
//    the verdict's window (health/verdict.h); CALIBRATION_HEALTH follows
//    each checked frame. Frames before any calibration, and frames of
//    another size, are counted (dropped, rejected);
//  - STEREO_COMMAND "refine" (target "" or "stereo-health"): refines the
//    extrinsics from the matches kept (health/extrinsic_refine.h); applied,
//    the corrected calibration is published on STEREO_CALIBRATION and used
//    at once; refused, the reason is the error and the command is counted as
//    rejected. Other commands to stereo-health are rejected;
//  - at the end of a file:// input: --refine, then --out and --report.
#pragma once

#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "health/extrinsic_refine.h"
#include "health/frame_checker.h"
#include "health/verdict.h"
#include "lcm_io/image_codec.h"
#include "rig/rig.h"
#include "runtime/command_dispatcher.h"
#include "runtime/process.h"
#include "widestereo/calibration_health_t.hpp"
#include "widestereo/command_t.hpp"
#include "widestereo/stereo_calibration_t.hpp"
#include "widestereo/stereo_frame_t.hpp"

namespace ws {

struct HealthConfig {
  RectifyOptions rectify;
  int64_t max_image_pixels = kDefaultMaxImagePixels;
  FeatureOptions features;
  VerdictOptions verdict;
  RefineOptions refine;
  DyGrid grid;
  double period_s = 1;
  int max_kept_matches = 20000;  // for refinement; the oldest frames' go first
  bool refine_at_end = false;
  std::string out_yaml, report_json;
};

class HealthNode {
 public:
  HealthNode(Process& process, HealthConfig config);

  // Subscribes, and starts from `calib_file` when not empty.
  void Start(const std::string& calib_file);

 private:
  // Throws std::invalid_argument for a calibration larger than
  // config.max_image_pixels, or that cannot be rectified, keeping the one before.
  void SetCalibration(const Rig& rig, const std::string& source);
  // The maps of the calibration in use, for its first frame.
  void BuildChecker();
  void OnCalibration(const widestereo::stereo_calibration_t& msg);
  void OnFrame(const widestereo::stereo_frame_t& frame);
  // refine: the calibration from the kept matches; throws when refused.
  void RefineCommand();
  void Check(const widestereo::stereo_frame_t& frame);
  widestereo::calibration_health_t Health(int64_t utime, int64_t frame_id) const;
  // Refines from the kept matches; applied, publishes and uses the result.
  RefineResult Refine();
  void AtEnd();

  Process& process_;
  const CommandDispatcher commands_;
  HealthConfig config_;
  std::optional<Rig> calibration_;
  cv::Size calibration_size_;
  std::optional<FrameChecker> checker_;  // once a frame of calibration_size_ came
  std::string source_;
  VerdictWindow window_;
  std::deque<std::vector<RayMatch>> kept_;  // per checked usable frame
  size_t kept_count_ = 0;
  int64_t last_check_utime_ = 0;
  int64_t last_frame_id_ = -1;
  int frames_checked_ = 0;
  int64_t frames_without_calibration_ = 0;
  std::optional<RefineResult> last_refine_;
  std::optional<widestereo::stereo_calibration_t> published_;  // the last refinement we published
};

}  // namespace ws
