#include "view/view_node.h"

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "lcm_io/channels.h"
#include "lcm_io/image_codec.h"
#include "rectify/calibration_size.h"
#include "rig/rig_message.h"
#include "runtime/wall_clock.h"
#include "view/page_events.h"
#include "widestereo/command_t.hpp"

namespace ws::view {
namespace {

using Policy = NewestFirst<int>::Policy;

template <class Msg>
NewestFirst<Msg> Stage(Process& process, const char* channel, std::function<void(Msg&)> work) {
  return NewestFirst<Msg>(process.file_input() ? NewestFirst<Msg>::Policy::in_line : NewestFirst<Msg>::Policy::newest,
                          std::move(work), [&process, channel](const Msg&) { process.Counters(channel).skipped++; });
}

// A stage's work: an event, or the reason it could not be made, counted as rejected.
template <class Fn>
void Guarded(Process& process, const char* channel, Fn fn) {
  try {
    fn();
  } catch (const std::exception& e) {
    process.HandleRejected(channel, e.what());
  }
}

// The process table, for the page to draw as HTML.
nlohmann::json ProcessTable(const std::vector<StatusBoard::ProcessRow>& rows) {
  nlohmann::json table = nlohmann::json::array();
  for (const auto& row : rows) {
    nlohmann::json channels = nlohmann::json::array();
    for (const auto& c : row.channels)
      channels.push_back({{"channel", c.channel},
                          {"in", c.in},
                          {"out", c.out},
                          {"rate", c.rate < 0 ? nlohmann::json() : nlohmann::json(c.rate)},
                          {"lost", c.lost},
                          {"skipped", c.skipped},
                          {"rejected", c.rejected}});
    table.push_back({{"who", row.who},
                     {"state", row.state},
                     {"pid", row.pid},
                     {"uptime", row.uptime},
                     {"ended", row.ended},
                     {"gone", row.gone},
                     {"channels", channels},
                     {"stages", row.stages},
                     {"last_error", row.last_error}});
  }
  return table;
}

}  // namespace

ViewNode::ViewNode(Process& process, EventHub& hub, BlobStore& blobs, const Audience& audience,
                   ViewOptions options)
    : process_(process),
      hub_(hub),
      blobs_(blobs),
      audience_(audience),
      options_(options),
      view_list_(blobs),
      frames_(Stage<widestereo::stereo_frame_t>(process, channel::kStereoImages,
                                                [this](auto& frame) { ShowFrame(frame); })),
      disparities_(Stage<widestereo::disparity_t>(process, channel::kStereoDisparity, [this](auto& d) {
        Guarded(process_, channel::kStereoDisparity,
                [&] { Show("disparity", DisparityEvent(d, options_.max_width, blobs_)); });
      })),
      clouds_(Stage<widestereo::point_cloud_t>(process, channel::kStereoCloudFiltered, [this](auto& c) {
        Show("cloud", CloudEvent(c, options_.cloud_points, blobs_));
      })) {
  if (!options_.recording.empty())
    recording_.emplace(options_.recording, options_.recording_cap_mb * 1e6, options_.recording_files);
}

ViewNode::~ViewNode() = default;

void ViewNode::SetRig(const Rig& rig, const std::string& source) {
  {
    std::lock_guard<std::mutex> lock(rig_mutex_);
    rig_ = rig;
    rig_source_ = source;
    rect_.reset();  // rebuilt by the frame thread for the next frame
  }
  Show("calibration", CalibrationEvent(MessageFromRig(rig, 0), source));
  process_.log().Info("depth view: rectifying with " + source);
}

std::string ViewNode::CommandsRefused() const {
  if (process_.options().key_file.empty())
    return "read-only: stereo-view was started without the rig key (--key-file), so it sends no "
           "commands";
  return "";
}

std::string ViewNode::Command(const std::string& command, std::optional<std::pair<int64_t, int64_t>> view) {
  if (std::string why = CommandsRefused(); !why.empty()) return why;
  if (command != "solve" && command != "save" && command != "reset" && command != "restore" && command != "remove")
    return "unknown command '" + command + "' (solve, save, reset, restore or remove)";
  if ((command == "remove") != view.has_value())
    return command == "remove" ? "remove names a view: its frame id and utime" : command + " takes no view";
  widestereo::command_t msg{};
  msg.utime = WallMicros();
  msg.command = command;
  msg.target = "stereo-calibrate";
  if (view) msg.args = {"frame=" + std::to_string(view->first), "utime=" + std::to_string(view->second)};
  msg.nargs = int32_t(msg.args.size());
  process_.Publish(channel::kStereoCommand, msg);  // signed with the rig key
  process_.log().Info("sent " + command + (view ? " " + msg.args[0] : "") + " to stereo-calibrate, from the page");
  return "";
}

Rectification ShownRectification(const Rig& rig, int max_width) {
  RectifyOptions options;
  options.mode = RectificationMode::kAuto;
  options.focal_scale = std::min(1.0, double(max_width) / rig.left.image_width);
  // The mode first, from the geometry alone (cheap); the maps once, at the
  // size shown.
  Rectification rect = RectificationGeometry(rig, options);
  if (rect.mode == RectificationMode::kPinhole && options.focal_scale != 1.0) {
    options.mode = RectificationMode::kPinhole;  // its size is the input's unless given
    options.size = cv::Size(int(std::lround(rig.left.image_width * options.focal_scale)),
                            int(std::lround(rig.left.image_height * options.focal_scale)));
    rect = RectificationGeometry(rig, options);
  }
  BuildRectificationMaps(rig, &rect);
  return rect;
}

int64_t ViewNode::Clock() const { return process_.file_input() ? process_.Now() : WallMicros(); }

void ViewNode::Show(const std::string& topic, std::string event) {
  hub_.Publish(topic, Arrived(std::move(event), Clock()));
}

bool ViewNode::Due(int64_t& last_us) {
  const int64_t now = process_.Now();
  if (last_us != INT64_MIN && now - last_us < int64_t(1e6 / options_.image_hz)) return false;
  last_us = now;
  return true;
}

void ViewNode::ShowFrame(widestereo::stereo_frame_t& frame) {
  Guarded(process_, channel::kStereoImages, [&] {
    if (audience_.Watching(PageView::kCalibration)) {
      std::string event = Arrived(FrameEvent(frame, options_.max_width, blobs_), Clock());
      {
        std::lock_guard<std::mutex> lock(recent_mutex_);
        recent_[frame.frame_id] = event;
        if (recent_.size() > kRecentFrames) recent_.erase(recent_.begin());
      }
      hub_.Publish("frame", std::move(event));
    }
    if (!audience_.Watching(PageView::kDepth) || IsNoImage(frame.right)) return;
    std::shared_ptr<const Rectification> rect;
    {
      std::lock_guard<std::mutex> lock(rig_mutex_);
      if (!rig_) return;
      // Before any map is built or pixel decoded.
      RequireFrameSize(frame, cv::Size(rig_->left.image_width, rig_->left.image_height), "the calibration");
      if (!rect_) rect_ = std::make_shared<const Rectification>(ShownRectification(*rig_, options_.max_width));
      rect = rect_;
    }
    const cv::Mat left = ImageView(frame.left), right = ImageView(frame.right);
    cv::Mat left_rect, right_rect;
    RectifyPair(*rect, left, right, &left_rect, &right_rect);
    Show("rectified", RectifiedEvent(frame.frame_id, left_rect, right_rect, options_.max_width, blobs_));
  });
}

void ViewNode::ShowCorners(const widestereo::stereo_corners_t& corners) {
  if (const auto measures = MeasureBoard(corners.left); measures && spread_.Add(*measures))
    Show("spread", spread_.Json().dump());
  std::lock_guard<std::mutex> lock(recent_mutex_);
  const auto frame = recent_.find(corners.frame_id);
  if (frame != recent_.end())
    hub_.Publish("detected", "{\"frame\":" + frame->second + ",\"corners\":" + CornersEvent(corners) + "}");
}

void ViewNode::PublishView() {
  nlohmann::json counters = nlohmann::json::object();
  for (const char* channel : {channel::kStereoImages, channel::kStereoDisparity, channel::kStereoCloudFiltered,
                              kBrowserCounters}) {
    const ChannelCounters& c = process_.Counters(channel);
    counters[channel] = {{"received", c.received.load()},
                         {"published", c.published.load()},
                         {"skipped", c.skipped.load()},
                         {"dropped", c.dropped.load()},
                         {"rejected", c.rejected.load()}};
  }
  std::string rig;
  {
    std::lock_guard<std::mutex> lock(rig_mutex_);
    rig = rig_source_;
  }
  const int64_t now = Clock();
  if (recording_) {
    // stereo-status shows the state, and a stopped recording as the last
    // error too (a later error replaces only that).
    if (recording_->Check(now) && !recording_->StoppedText().empty()) process_.ReportError(recording_->StoppedText());
    if (const std::string state = recording_->StateText(); !state.empty()) process_.SetState(state);
  }
  hub_.Publish("status", nlohmann::json{{"commands_refused", CommandsRefused()},
                                        {"calibration", rig},
                                        {"counters", counters},
                                        {"now_us", now},
                                        {"first_view", options_.first_view},
                                        {"freshness", freshness_.Json(now)},
                                        {"recording", recording_ ? recording_->Json() : nlohmann::json()},
                                        {"processes", ProcessTable(board_.Rows(now))}}
                             .dump());
}

template <class Msg>
void ViewNode::SubscribeSampled(const char* channel, Audience::Views views, int64_t& last_us,
                                NewestFirst<Msg>& stage, Process::FrameGaps gaps) {
  process_.SubscribeSampled<Msg>(
      channel,
      [this, channel, views, &last_us] {
        freshness_.Heard(channel, Clock());  // asked once for every message that comes
        return audience_.Watching(views) && Due(last_us);
      },
      [&stage](Msg& msg) { stage.Offer(std::move(msg)); },
      2,  // LCM's queue holds two big messages at most: the stage takes the newest
      gaps);
}

template <class Msg>
void ViewNode::SubscribeShown(const char* channel, std::function<void(const Msg&)> show,
                              Process::FrameGaps gaps) {
  process_.Subscribe<Msg>(
      channel,
      [this, channel, show = std::move(show)](const Msg& msg) {
        freshness_.Heard(channel, Clock());
        show(msg);
      },
      0, gaps);
}

void ViewNode::Start() {
  const bool live = !process_.file_input();
  const Audience::Views depth{/*calibration=*/false, /*depth=*/true};
  // The channels that carry only the frames their sender looked at (a
  // newest-frame stage, a once-a-second check): gaps there are skips by
  // design, not losses (runtime/process.h).
  constexpr auto sparse = Process::FrameGaps::skipped;
  SubscribeSampled(channel::kStereoImages, Audience::Views{}, last_frame_us_, frames_);
  process_.Subscribe<widestereo::stereo_frame_t>(
      channel::kStereoThumbnails,
      [this](const widestereo::stereo_frame_t& m) {
        Guarded(process_, channel::kStereoThumbnails, [&] { view_list_.Found(m); });
      },
      0, sparse);  // only the frames with a board
  SubscribeShown<widestereo::stereo_corners_t>(
      channel::kStereoCorners, [this](const auto& m) { ShowCorners(m); }, sparse);
  SubscribeShown<widestereo::calibration_status_t>(channel::kCalibrationStatus, [this](const auto& m) {
    board_.Add(m);
    if (m.views_left + m.views_right < views_) {  // stereo-calibrate was reset: its views are gone
      spread_.Clear();
      Show("spread", spread_.Json().dump());
    }
    views_ = m.views_left + m.views_right;
    Show("coverage", CoverageEvent(m));
  });
  SubscribeShown<widestereo::calibration_views_t>(channel::kCalibrationViews, [this](const auto& m) {
    if (auto update = view_list_.Event(m))
      hub_.Publish("views", Arrived(std::move(update->whole), Clock()), Arrived(std::move(update->change), Clock()));
  });
  process_.Subscribe<widestereo::calibration_result_t>(
      channel::kCalibrationResult, [this](const auto& m) { Show("result", ResultEvent(m)); });
  process_.Subscribe<widestereo::calibration_result_t>(
      channel::kCalibrationPreview, [this](const auto& m) { Show("preview", ResultEvent(m)); });
  process_.Subscribe<widestereo::stereo_calibration_t>(channel::kStereoCalibration, [this](const auto& m) {
    SetRig(RigFromMessage(m), "the STEREO_CALIBRATION of utime " + std::to_string(m.utime));
  });
  SubscribeSampled(channel::kStereoDisparity, depth, last_disparity_us_, disparities_, sparse);
  SubscribeSampled(channel::kStereoCloudFiltered, depth, last_cloud_us_, clouds_, sparse);
  SubscribeShown<widestereo::cloud_stats_t>(
      channel::kCloudStats,
      [this](const auto& m) {
        board_.Add(m, Clock());
        Show("cloud_stats", CloudStatsEvent(m));
      },
      sparse);
  SubscribeShown<widestereo::calibration_health_t>(
      channel::kCalibrationHealth,
      [this](const auto& m) {
        board_.Add(m);
        Show("health", HealthEvent(m));
      },
      sparse);
  process_.Subscribe<widestereo::process_status_t>(
      channel::kProcessStatus, [this](const auto& m) { board_.Add(m, Clock()); });
  process_.Every(1000000, [this] { PublishView(); });
  if (live) PublishView();
}

}  // namespace ws::view
