// The page's events (view/event_hub.h topics), one JSON text per message the
// page shows. Images and clouds go to a BlobStore (view/blob_store.h) and the
// event names their path ("src"): images as JPEG scaled to at most
// `max_width` pixels across, clouds as little-endian float32 x y z triples.
// Each takes a message already validated (lcm_io/validate.h). The store
// keeps kFramesKept frame images (the recent frames that corners may still
// come for) and kPayloadsKept of each other topic.
#pragma once

#include <cstdint>
#include <string>

#include <opencv2/core.hpp>

#include "view/blob_store.h"
#include "widestereo/calibration_health_t.hpp"
#include "widestereo/calibration_result_t.hpp"
#include "widestereo/calibration_status_t.hpp"
#include "widestereo/cloud_stats_t.hpp"
#include "widestereo/disparity_t.hpp"
#include "widestereo/point_cloud_t.hpp"
#include "widestereo/stereo_corners_t.hpp"
#include "widestereo/stereo_calibration_t.hpp"
#include "widestereo/stereo_frame_t.hpp"

namespace ws::view {

inline constexpr size_t kFramesKept = 64;   // 21 s at 3 Hz: a slow detector's latency
inline constexpr size_t kPayloadsKept = 4;  // a browser fetches them right after their event

// Topic "frame": both images (no "right" for a one-camera rig).
std::string FrameEvent(const widestereo::stereo_frame_t& frame, int max_width, BlobStore& blobs);
// The corners found in each image, pixels of the full image (topic
// "detected": {"frame": a FrameEvent, "corners": this}).
std::string CornersEvent(const widestereo::stereo_corners_t& corners);
// Topic "coverage": stereo-calibrate's state, views, coverage grids, RMS and hint.
std::string CoverageEvent(const widestereo::calibration_status_t& status);
// Topic "result": the model table, the chosen model, its maps.
std::string ResultEvent(const widestereo::calibration_result_t& result);
// Topic "calibration": the calibration in use (`source`: where it came
// from): each camera's model, K (fx, fy, cx, cy), its distortion
// coefficients (the B-spline's alpha, or k1..kn) and p1, p2; R, T and the
// baseline |T|.
std::string CalibrationEvent(const widestereo::stereo_calibration_t& calibration, const std::string& source);
// Topic "rectified": the rectified pair of a frame (rows are epipolar lines).
std::string RectifiedEvent(int64_t frame_id, const cv::Mat& left, const cv::Mat& right, int max_width,
                           BlobStore& blobs);
// Topic "disparity": the colour image and its legend (view/disparity_colour.h).
std::string DisparityEvent(const widestereo::disparity_t& disparity, int max_width, BlobStore& blobs);
// Topic "cloud": at most `max_points` of the cloud's points, evenly taken.
std::string CloudEvent(const widestereo::point_cloud_t& cloud, int max_points, BlobStore& blobs);
// Topic "cloud_stats": the points after each of stereo-cloud's stages, the plane.
std::string CloudStatsEvent(const widestereo::cloud_stats_t& stats);
// Topic "health": stereo-health's verdict and |dy| figures.
std::string HealthEvent(const widestereo::calibration_health_t& health);

// `event` (a JSON object) with "at_us": when stereo-view received what it
// shows (its own clock), so that the page can show its age.
std::string Arrived(std::string event, int64_t at_us);

// An 8-bit image (gray or BGR) scaled to at most max_width across, as a JPEG blob.
Blob Jpeg(const cv::Mat& image, int max_width);
// An image message as Jpeg makes it: decoded after its size is checked
// (lcm_io/image_codec.h ImageView), 16-bit and float images scaled to 8 bits.
// Throws DecodeError.
Blob ImageJpeg(const widestereo::image_t& image, int max_width);

}  // namespace ws::view
