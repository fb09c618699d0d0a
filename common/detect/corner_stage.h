// stereo-detect's work inside a Process: every STEREO_IMAGES frame goes
// through a StereoCornerFinder on an OrderedPipeline, and its corners are
// published on STEREO_CORNERS in input order.
//
// - A frame in which either camera saw the board is also published on
//   STEREO_THUMBNAILS, just before its corners, as the small image the page
//   lists its view with (detect/thumbnail_frame.h).
//
// - Every frame that decodes is published, also when neither camera sees the
//   board (n = 0 for both): the calibrator learns that the frame happened, and
//   its frame-id gap count stays a count of frames lost.
// - A frame with an image that does not decode, or is too small for the board,
//   is counted as rejected on STEREO_IMAGES and logged, and not published.
// - Live, a frame that arrives while max_in_flight frames are in flight is
//   dropped (counted as dropped on STEREO_IMAGES). Replaying a log, the input
//   waits instead: nothing is dropped and the output is the same every time.
// - A frame with corners dropped because their refinement failed
//   (corner_refinement.h) is logged with how many, and the progress line
//   counts them.
#pragma once

#include <atomic>
#include <cstdint>
#include <string>

#include "detect/stereo_corner_finder.h"
#include "runtime/ordered_pipeline.h"
#include "runtime/process.h"

namespace ws {

class CornerStage {
 public:
  // Subscribes `process` to STEREO_IMAGES; drains itself at the end of a
  // file:// input. `finder` must outlive the stage.
  CornerStage(Process& process, const StereoCornerFinder& finder, int workers, int max_in_flight);
  // Publishes every frame still in flight.
  ~CornerStage();

  // "boards left L right R of N frames | in flight K (peak P)", then
  // "| unrefined corners dropped D" once there are any, for the progress line.
  std::string Progress() const;

 private:
  void OnFrame(const widestereo::stereo_frame_t& frame);
  // Runs on a worker: the finder's result, as the step that publishes it.
  OrderedPipeline::Delivery Detect(const widestereo::stereo_frame_t& frame);
  // `thumbnail`: null when neither camera saw the board.
  void Deliver(const widestereo::stereo_corners_t& corners, const widestereo::stereo_frame_t* thumbnail,
               int unrefined);
  void Reject(int64_t frame_id, const std::string& why);

  Process& process_;
  const StereoCornerFinder& finder_;
  ChannelCounters& images_;
  OrderedPipeline pipeline_;
  std::atomic<int64_t> frames_{0}, left_boards_{0}, right_boards_{0}, unrefined_{0};
};

}  // namespace ws
