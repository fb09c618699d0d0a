#include "detect/corner_stage.h"

#include <memory>

#include "detect/thumbnail_frame.h"
#include "lcm_io/channels.h"

namespace ws {

CornerStage::CornerStage(Process& process, const StereoCornerFinder& finder, int workers,
                         int max_in_flight)
    : process_(process),
      finder_(finder),
      images_(process.Counters(channel::kStereoImages)),
      pipeline_({workers, max_in_flight,
                 process.file_input() ? OrderedPipeline::WhenFull::wait
                                      : OrderedPipeline::WhenFull::refuse}) {
  // Live, LCM's own queue in front of the handler holds no more frames than
  // the pipeline: the handler only hands frames over, so it rarely holds any.
  process.Subscribe<widestereo::stereo_frame_t>(
      channel::kStereoImages, [this](const auto& frame) { OnFrame(frame); }, max_in_flight);
  process.AtEndOfInput([this] { pipeline_.Drain(); });
}

// Live, a stopping detector finishes the frames it is detecting and drops
// (and counts) the ones it has not begun; from a file it detects them all.
CornerStage::~CornerStage() {
  if (!process_.file_input()) images_.dropped += pipeline_.DropNotStarted();
  pipeline_.Drain();
}

std::string CornerStage::Progress() const {
  return "boards left " + std::to_string(left_boards_) + " right " + std::to_string(right_boards_) +
         " of " + std::to_string(frames_) + " frames | in flight " +
         std::to_string(pipeline_.in_flight()) + " (peak " + std::to_string(pipeline_.peak_in_flight()) + ")" +
         (unrefined_ > 0 ? " | unrefined corners dropped " + std::to_string(unrefined_) : "");
}

void CornerStage::OnFrame(const widestereo::stereo_frame_t& frame) {
  auto copy = std::make_shared<const widestereo::stereo_frame_t>(frame);
  if (!pipeline_.Submit([this, copy] { return Detect(*copy); })) images_.dropped++;
}

OrderedPipeline::Delivery CornerStage::Detect(const widestereo::stereo_frame_t& frame) {
  try {
    int unrefined = 0;
    auto corners = std::make_shared<const widestereo::stereo_corners_t>(finder_.Find(frame, &unrefined));
    std::shared_ptr<const widestereo::stereo_frame_t> thumbnail;
    if (corners->left.n > 0 || corners->right.n > 0)
      thumbnail = std::make_shared<const widestereo::stereo_frame_t>(ThumbnailFrame(frame, *corners));
    return [this, corners, thumbnail, unrefined] { Deliver(*corners, thumbnail.get(), unrefined); };
  } catch (const std::exception& e) {
    return [this, id = frame.frame_id, why = std::string(e.what())] { Reject(id, why); };
  }
}

void CornerStage::Deliver(const widestereo::stereo_corners_t& corners,
                          const widestereo::stereo_frame_t* thumbnail, int unrefined) {
  frames_++;
  if (unrefined > 0) {
    unrefined_ += unrefined;
    process_.log().Detail("frame " + std::to_string(corners.frame_id) + ": " + std::to_string(unrefined) +
                          " corners dropped, their refinement failed (left at whole pixels)");
  }
  if (corners.left.n > 0) left_boards_++;
  if (corners.right.n > 0) right_boards_++;
  // The thumbnail first: stereo-view holds it for the corners that follow.
  if (thumbnail) process_.Publish(channel::kStereoThumbnails, *thumbnail);
  process_.Publish(channel::kStereoCorners, corners);
}

void CornerStage::Reject(int64_t frame_id, const std::string& why) {
  images_.rejected++;
  process_.ReportRecurring(std::string(channel::kStereoImages) + ": frame " + std::to_string(frame_id) +
                       " rejected: " + why);
}

}  // namespace ws
