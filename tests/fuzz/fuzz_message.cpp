// One libFuzzer target per LCM message type (the compile definition
// WS_FUZZ_MESSAGE names it): the decode and Validate every subscriber runs,
// then what the processes do next with an accepted message of that type.
// Anything but a DecodeError from decoding, a crash, a sanitizer report or a
// broken property is a finding; the processes catch std::exception from their
// handlers, so the steps after decoding may throw those.
#include <cmath>
#include <stdexcept>
#include <type_traits>

#include "auth/message_auth.h"
#include "calib/node/calibration_session.h"
#include "cloud/cloud_filter.h"
#include "detect/thumbnail_frame.h"
#include "fuzz_support.h"
#include "lcm_io/channels.h"
#include "lcm_io/image_codec.h"
#include "monitor/status_board.h"
#include "rectify/calibration_size.h"
#include "rig/rig_message.h"
#include "view/page_events.h"
#include "view/view_list.h"

// Not in an anonymous namespace: each binary uses only its type's overload.
namespace ws::fuzz {

using namespace widestereo;

// stereo-detect and stereo-match read every image through ImageToMat.
void Use(const image_t& image) {
  const cv::Mat mat = ws::ImageToMat(image);
  if (mat.cols != image.width || mat.rows != image.height || !mat.isContinuous())
    Violated("ImageToMat gave " + std::to_string(mat.cols) + "x" + std::to_string(mat.rows) +
             " for a " + std::to_string(image.width) + "x" + std::to_string(image.height) +
             " image");
}

// A receiver with a rig key checks every command, calibration, corners
// message and image pair (the MAC over the message re-encoded, the key, the
// time, the nonce); the same message signed anew with the key passes that
// check.
template <class Msg>
void Authenticate(const Msg& msg, const char* channel) {
  ws::auth::AuthCheck check(FuzzKey());
  try {
    check.Check(channel, msg, msg.auth.utime);
  } catch (const ws::auth::AuthError&) {
  }
  Msg resigned = msg;
  ws::auth::Sign(FuzzKey(), channel, msg.auth.sender, msg.auth.utime, resigned);
  try {
    check.Check(channel, resigned, msg.auth.utime);
  } catch (const ws::auth::AuthError& e) {
    Violated(std::string("a message signed with the key is refused: ") + e.what());
  }
}

void Use(const stereo_frame_t& frame) {
  Authenticate(frame, ws::channel::kStereoImages);
  Use(frame.left);
  if (!ws::IsNoImage(frame.right)) Use(frame.right);  // a one-camera rig's (stereo-capture --mono)
  // stereo-detect makes a thumbnail of a frame it found the board in, and
  // stereo-view lists what comes on STEREO_THUMBNAILS (a frame as any other).
  widestereo::stereo_corners_t corners{};
  corners.frame_id = frame.frame_id;
  corners.utime = frame.utime;
  corners.left.n = 1;
  try {
    ws::ThumbnailFrame(frame, corners);
  } catch (const ws::DecodeError&) {
  }
  ws::view::BlobStore blobs;
  ws::view::ViewList list(blobs);
  try {
    list.Found(frame);
  } catch (const ws::DecodeError&) {
  }
}

// stereo-view colours every disparity it shows (stereo-match --save-disparity likewise).
void Use(const disparity_t& disparity) {
  Use(disparity.disparity);
  ws::view::BlobStore blobs;
  ws::view::DisparityEvent(disparity, 64, blobs);
}

// stereo-match turns a calibration into camera models and unprojects every
// pixel: a pixel that unprojects must project back onto itself.
void Use(const camera_calibration_t& calibration) {
  const ws::Camera camera(ws::CameraModelFromMessage(calibration));
  const double w = calibration.image_width, h = calibration.image_height;
  const double scale = std::max(calibration.fx, calibration.fy);
  for (const Eigen::Vector2d& pixel : {Eigen::Vector2d(-0.5, -0.5), Eigen::Vector2d(w / 2, h / 2),
                                      Eigen::Vector2d(w - 0.5, h - 0.5), Eigen::Vector2d(0, h / 3)}) {
    const auto ray = camera.Unproject(pixel);
    if (!ray) continue;
    const auto back = camera.Project(*ray);
    const double distorted = std::hypot((pixel.x() - calibration.cx) / calibration.fx,
                                        (pixel.y() - calibration.cy) / calibration.fy);
    if (!back || !((*back - pixel).norm() <= 1e-6 * scale * (1 + distorted)))
      Violated("pixel (" + std::to_string(pixel.x()) + ", " + std::to_string(pixel.y()) +
               ") unprojects to a ray that does not project back onto it");
  }
}

void Use(const command_t& command) { Authenticate(command, ws::channel::kStereoCommand); }

void Use(const stereo_calibration_t& calibration) {
  Authenticate(calibration, ws::channel::kStereoCalibration);
  Use(calibration.left);
  Use(calibration.right);
  // stereo-match and stereo-health check its sizes and geometry before any map.
  ws::RectifyOptions options;
  options.mode = ws::RectificationMode::kAuto;
  ws::CalibrationGeometry(ws::RigFromMessage(calibration), options, ws::kDefaultMaxImagePixels, "it");
}

// stereo-status shows every status it hears.
template <class Status>
void Show(const Status& status) {
  ws::StatusBoard board;
  for (int64_t heard_us : {0, 1000000}) {
    if constexpr (std::is_same_v<Status, process_status_t>)
      board.Add(status, heard_us);
    else
      board.Add(status);
  }
  board.Render(10000000, {40, 10});  // gone, condensed, cut
  board.Render(1000000);
}
void Use(const process_status_t& status) { Show(status); }
void Use(const calibration_status_t& status) {
  Show(status);
  ws::view::CoverageEvent(status);
}
void Use(const calibration_health_t& health) { Show(health); }

// stereo-view shows every cloud; stereo-cloud decodes the same bytes as a
// PointCloud and runs its filter chain on it.
void Use(const point_cloud_t& cloud) {
  static const ws::CloudFilter filter{ws::CloudFilterConfig{}};
  ws::view::BlobStore blobs;
  ws::view::CloudEvent(cloud, 100, blobs);
  const std::vector<uint8_t> bytes = ws::EncodeMessage(cloud);
  filter.Run(ws::DecodeMessage<ws::PointCloud>(bytes.data(), int(bytes.size())));
}

// stereo-view shows every solve's outcome and every calibration status.
void Use(const calibration_result_t& result) { ws::view::ResultEvent(result); }

// stereo-view lists every view stereo-calibrate holds (no frame at hand: no thumbnail).
void Use(const calibration_views_t& views) {
  ws::view::BlobStore blobs;
  ws::view::ViewList list(blobs);
  if (!list.Event(views) || list.Event(views)) Violated("the same views listed twice, or not at all");
}

// stereo-calibrate adds every corners message to its session (the view, the
// coverage grids, the near-duplicate check) and publishes the status.
void Use(const stereo_corners_t& corners) {
  Authenticate(corners, ws::channel::kStereoCorners);
  ws::calib::CalibrationSession session{ws::calib::SessionOptions{}};
  for (int i = 0; i < 2; ++i) session.Add(corners);  // the second one is a near duplicate
  session.Status(0, "collecting", -1);
  ws::view::CornersEvent(corners);  // stereo-view draws them
  if (session.views() > 1) Violated("the same view was accepted twice");
}

// Single-camera corners and cloud statistics are used as decoded.
template <class Msg>
void Use(const Msg&) {}

}  // namespace ws::fuzz

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto msg = ws::fuzz::DecodeAccepted<WS_FUZZ_MESSAGE>(data, size);
  if (!msg) return 0;
  try {
    ws::fuzz::Use(*msg);
  } catch (const std::exception&) {
    // A handler's exception: the process counts the message as rejected.
  }
  return 0;
}
