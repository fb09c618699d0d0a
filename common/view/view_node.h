// stereo-view's bus side: turns what the page shows into events on an
// EventHub (view/event_hub.h) and the page's buttons into commands.
//
//  - STEREO_IMAGES at most `image_hz` (JPEG, both images; with a calibration
//    also the rectified pair); STEREO_CORNERS with the image they were found
//    in (when that frame was one of the last kRecentFrames shown: the
//    corners of other frames are not drawn), and every board's measures
//    (view/board_spread.h: camera_calibration's bars), CALIBRATION_STATUS,
//    CALIBRATION_RESULT and CALIBRATION_PREVIEW (the uncertainty of the
//    views so far, before a solve): the calibration view;
//  - STEREO_CALIBRATION (and --calib): the calibration in use, K, the
//    distortion, R, T, the baseline;
//  - STEREO_DISPARITY (colours and legend, at most image_hz),
//    STEREO_CLOUD_FILTERED (at most image_hz), CLOUD_STATS,
//    CALIBRATION_HEALTH: the depth view;
//  - PROCESS_STATUS and the rest: stereo-status's table, every second, with
//    each channel's freshness (view/freshness.h); every event carries when
//    it was received (view/page_events.h Arrived).
//
// The images, disparities and clouds are turned into events on threads of
// their own (runtime/newest_first.h), so the input thread only hands them
// over: one that arrives within 1 / image_hz of the last shown (live, not
// even decoded: Process::SubscribeSampled), or is replaced by a newer one
// before its thread took it, is counted as skipped on its channel. From a
// file:// log everything runs in line. A view's frames are made only while
// some browser shows that view (view/audience.h); the others are skipped
// undecoded, as sampled ones are.
//
// CALIBRATION_VIEWS: the list of views with their thumbnails (view/view_list.h),
// as a change from the list before. stereo-detect sends a thumbnail of each
// frame it found a board in (STEREO_THUMBNAILS, detect/thumbnail_frame.h)
// just before its corners, so that every view gets one, whatever the page
// was shown and whichever full frames this process dropped.
//
// Commands (Command): solve, save, reset, restore to stereo-calibrate, no
// arguments (the page names no file), and remove with the view's frame id
// and utime; sent signed, and only with the rig key.
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "monitor/status_board.h"
#include "rectify/rectification.h"
#include "runtime/newest_first.h"
#include "runtime/process.h"
#include "view/audience.h"
#include "view/blob_store.h"
#include "view/board_spread.h"
#include "view/event_hub.h"
#include "view/freshness.h"
#include "view/page_events.h"
#include "view/recording_watch.h"
#include "view/view_list.h"
#include "widestereo/disparity_t.hpp"
#include "widestereo/point_cloud_t.hpp"
#include "widestereo/stereo_frame_t.hpp"

namespace ws::view {

struct ViewOptions {
  double image_hz = 3;      // images, disparities and clouds shown per second at most
  int max_width = 640;      // pixels across of the images sent to the page
  int cloud_points = 20000; // points of a cloud sent to the page at most
  std::string first_view = "calibration";  // the tab a page opens on (the launch's purpose)
  std::string recording;        // the launch's LCM log ("": none), its size shown against...
  double recording_cap_mb = 500;  // ...the size at which the launcher stops it (rolling: that it keeps)
  int recording_files = 1;        // 1, or a rolling recording's files (view/recording_watch.h)
};

// The pseudo-channel of PROCESS_STATUS counting the page's events: published
// (sent to a browser), skipped (replaced before a slow browser took it).
inline constexpr const char* kBrowserCounters = "browsers";

// The rectification the page shows: `auto` (stereo-match's default), at a
// focal length scaled so that the rectified images are at most max_width
// across (rectified that small, not shrunk after).
Rectification ShownRectification(const Rig& rig, int max_width);

class ViewNode {
 public:
  ViewNode(Process& process, EventHub& hub, BlobStore& blobs, const Audience& audience, ViewOptions options);
  ~ViewNode();

  // The calibration the depth view rectifies with until a STEREO_CALIBRATION comes.
  void SetRig(const Rig& rig, const std::string& source);
  void Start();

  // Whether the page may send commands, and why not ("" when it may).
  std::string CommandsRefused() const;
  // Sends `command` (solve, save, reset, restore; or remove, of the view of
  // frame `view`: its frame id and utime) to stereo-calibrate; "" when sent,
  // else why not (then nothing is sent).
  std::string Command(const std::string& command, std::optional<std::pair<int64_t, int64_t>> view = std::nullopt);

 private:
  static constexpr size_t kRecentFrames = kFramesKept;  // view/page_events.h

  // stereo-view's clock: the wall clock live, the log's from a file.
  int64_t Clock() const;
  // Publishes an event stamped with when it was made (view/page_events.h Arrived).
  void Show(const std::string& topic, std::string event);
  bool Due(int64_t& last_us);
  // Hands a message of `channel` to `stage` when a browser shows one of
  // `views` and at least 1 / image_hz has passed since `last_us`; else
  // counts it as skipped. Every message is heard (freshness_).
  template <class Msg>
  void SubscribeSampled(const char* channel, Audience::Views views, int64_t& last_us, NewestFirst<Msg>& stage,
                        Process::FrameGaps gaps = Process::FrameGaps::count);
  // Subscribes `show` to `channel`, every message heard (freshness_).
  template <class Msg>
  void SubscribeShown(const char* channel, std::function<void(const Msg&)> show,
                      Process::FrameGaps gaps = Process::FrameGaps::count);
  void ShowCorners(const widestereo::stereo_corners_t& corners);
  void ShowFrame(widestereo::stereo_frame_t& frame);
  void PublishView();

  Process& process_;
  EventHub& hub_;
  BlobStore& blobs_;
  const Audience& audience_;
  ViewOptions options_;
  StatusBoard board_;
  Freshness freshness_;
  std::optional<RecordingWatch> recording_;
  BoardSpread spread_;  // of every board stereo-detect found (the input thread's)
  ViewList view_list_;  // the input thread's, as is the next
  int views_ = 0;       // stereo-calibrate's views at its last status
  int64_t last_frame_us_ = INT64_MIN, last_disparity_us_ = INT64_MIN, last_cloud_us_ = INT64_MIN;
  std::mutex rig_mutex_;  // guards rig_, rig_source_, rect_ (the frame thread builds rect_)
  std::optional<Rig> rig_;
  std::string rig_source_;
  std::shared_ptr<const Rectification> rect_;
  std::mutex recent_mutex_;  // guards recent_
  std::map<int64_t, std::string> recent_;  // the frames shown last, their "frame" events by frame id
  NewestFirst<widestereo::stereo_frame_t> frames_;
  NewestFirst<widestereo::disparity_t> disparities_;
  NewestFirst<widestereo::point_cloud_t> clouds_;
};

}  // namespace ws::view
