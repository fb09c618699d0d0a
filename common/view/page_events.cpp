#include "view/page_events.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "lcm_io/image_codec.h"
#include "view/disparity_colour.h"

namespace ws::view {
namespace {

using nlohmann::json;

// Any image the bus carries as 8 bits a channel (16-bit and float ones scaled).
cv::Mat To8Bit(const cv::Mat& image) {
  if (image.depth() == CV_8U) return image;
  cv::Mat out;
  if (image.depth() == CV_16U)
    image.convertTo(out, CV_8U, 1.0 / 257);
  else
    cv::normalize(image, out, 0, 255, cv::NORM_MINMAX, CV_8U);
  return out;
}

json Image(const widestereo::image_t& image, int max_width, BlobStore& blobs) {
  return {{"width", image.width}, {"height", image.height}, {"src", blobs.Put("frame", 2 * kFramesKept, ImageJpeg(image, max_width))}};
}

json Corners(const widestereo::camera_corners_t& corners) {
  json points = json::array();
  for (int i = 0; i < corners.n; ++i) points.push_back({corners.image_points[i][0], corners.image_points[i][1]});
  return {{"width", corners.image_width}, {"height", corners.image_height}, {"points", points}};
}

// A negative value ("none") as null.
json Figure(double value) { return value < 0 ? json(nullptr) : json(value); }

template <class Grid>
json Rows(const Grid& grid) {
  json rows = json::array();
  for (const auto& row : grid) rows.push_back(row);
  return rows;
}

}  // namespace

Blob Jpeg(const cv::Mat& image, int max_width) {
  cv::Mat shown = image;
  if (image.cols > max_width)
    cv::resize(image, shown, {max_width, std::max(1, image.rows * max_width / image.cols)}, 0, 0,
               cv::INTER_AREA);
  Blob jpeg{"image/jpeg", {}};
  cv::imencode(".jpg", shown, jpeg.bytes, {cv::IMWRITE_JPEG_QUALITY, 80});
  return jpeg;
}

Blob ImageJpeg(const widestereo::image_t& image, int max_width) { return Jpeg(To8Bit(ImageView(image)), max_width); }

std::string Arrived(std::string event, int64_t at_us) {
  if (event.size() < 2 || event.front() != '{' || event.back() != '}')
    throw std::logic_error("an event is a JSON object");
  event.insert(event.size() - 1, std::string(event.size() > 2 ? "," : "") + "\"at_us\":" + std::to_string(at_us));
  return event;
}

std::string FrameEvent(const widestereo::stereo_frame_t& frame, int max_width, BlobStore& blobs) {
  json event = {
      {"frame_id", frame.frame_id}, {"utime", frame.utime}, {"left", Image(frame.left, max_width, blobs)}};
  if (!IsNoImage(frame.right)) event["right"] = Image(frame.right, max_width, blobs);
  return event.dump();
}

std::string CornersEvent(const widestereo::stereo_corners_t& corners) {
  return json{{"frame_id", corners.frame_id},
              {"board", corners.left.board_id},
              {"left", Corners(corners.left)},
              {"right", Corners(corners.right)}}
      .dump();
}

std::string CoverageEvent(const widestereo::calibration_status_t& status) {
  return json{{"state", status.state},
              {"views_left", status.views_left},
              {"views_right", status.views_right},
              {"views_stereo", status.views_stereo},
              {"grid_rows", status.grid_rows},
              {"grid_cols", status.grid_cols},
              {"coverage_left", Rows(status.coverage_left)},
              {"coverage_right", Rows(status.coverage_right)},
              {"rms", Figure(status.rms)},
              {"heldout_rms", Figure(status.heldout_rms)},
              {"hint", status.hint}}
      .dump();
}

std::string ResultEvent(const widestereo::calibration_result_t& result) {
  json models = json::array(), cameras = json::array();
  for (const auto& m : result.models)
    models.push_back({{"model", m.model},
                      {"error", m.error},
                      {"left_rms", Figure(m.left_rms)},
                      {"left_heldout_rms", Figure(m.left_heldout_rms)},
                      {"right_rms", Figure(m.right_rms)},
                      {"right_heldout_rms", Figure(m.right_heldout_rms)},
                      {"stereo_rms", Figure(m.stereo_rms)}});
  for (const auto& c : result.cameras)
    cameras.push_back({{"name", c.name},
                       {"width", c.image_width},
                       {"height", c.image_height},
                       {"residual_rms_px", Rows(c.residual_rms_px)},
                       {"uncertainty_px", Rows(c.uncertainty_px)}});
  return json{{"utime", result.utime}, {"chosen", result.chosen}, {"models", models}, {"cameras", cameras}}.dump();
}

std::string CalibrationEvent(const widestereo::stereo_calibration_t& calibration, const std::string& source) {
  json cameras = json::array();
  for (const auto* c : {&calibration.left, &calibration.right}) {
    if (c->image_width <= 0) continue;  // a one-camera rig
    cameras.push_back({{"name", c->name},
                       {"width", c->image_width},
                       {"height", c->image_height},
                       {"model", c->model},
                       {"K", {{c->fx, 0, c->cx}, {0, c->fy, c->cy}, {0, 0, 1}}},
                       {"coeffs", c->coeffs},
                       {"p1", c->p1},
                       {"p2", c->p2},
                       {"rms", Figure(c->rms)}});
  }
  json R = json::array();
  for (int r = 0; r < 3; ++r) R.push_back({calibration.R[3 * r], calibration.R[3 * r + 1], calibration.R[3 * r + 2]});
  const auto& T = calibration.T;
  return json{{"source", source},
              {"cameras", cameras},
              {"R", R},
              {"T", {T[0], T[1], T[2]}},
              {"baseline", std::sqrt(T[0] * T[0] + T[1] * T[1] + T[2] * T[2])}}
      .dump();
}

std::string RectifiedEvent(int64_t frame_id, const cv::Mat& left, const cv::Mat& right, int max_width,
                           BlobStore& blobs) {
  return json{{"frame_id", frame_id},
              {"width", left.cols},
              {"height", left.rows},
              {"left", blobs.Put("rectified", 2 * kPayloadsKept, Jpeg(To8Bit(left), max_width))},
              {"right", blobs.Put("rectified", 2 * kPayloadsKept, Jpeg(To8Bit(right), max_width))}}
      .dump();
}

std::string DisparityEvent(const widestereo::disparity_t& disparity, int max_width, BlobStore& blobs) {
  const DisparityLegend legend = MakeLegend(disparity);
  cv::Mat values = ImageView(disparity.disparity);
  if (values.cols > max_width)  // coloured at the size shown: nearest, so no disparity is made up
    cv::resize(values, values, {max_width, std::max(1, values.rows * max_width / values.cols)}, 0, 0,
               cv::INTER_NEAREST);
  const cv::Mat colour = ColourDisparity(values, legend);
  json ticks = json::array();
  for (const LegendTick& tick : legend.ticks)
    ticks.push_back({{"disparity", tick.disparity},
                     {"metres", tick.metres},
                     {"rgb", {tick.bgr[2], tick.bgr[1], tick.bgr[0]}}});
  return json{{"frame_id", disparity.frame_id},
              {"rectification", disparity.rectification == widestereo::disparity_t::RECTIFICATION_LATLON
                                    ? "latlon"
                                    : "pinhole"},
              {"f", disparity.f},
              {"baseline", disparity.baseline},
              {"min_disparity", legend.min_disparity},
              {"max_disparity", legend.max_disparity},
              {"ticks", ticks},
              {"src", blobs.Put("disparity", kPayloadsKept, Jpeg(colour, max_width))}}
      .dump();
}

std::string CloudEvent(const widestereo::point_cloud_t& cloud, int max_points, BlobStore& blobs) {
  static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "the page reads float32 little-endian");
  const int step = std::max(1, (cloud.npoints + max_points - 1) / std::max(1, max_points));
  Blob xyz{"application/octet-stream", {}};
  xyz.bytes.reserve(size_t(cloud.npoints / step + 1) * 3 * sizeof(float));
  for (int i = 0; i < cloud.npoints; i += step) {
    const auto* point = reinterpret_cast<const uint8_t*>(cloud.xyz[i].data());
    xyz.bytes.insert(xyz.bytes.end(), point, point + 3 * sizeof(float));
  }
  const size_t shown = xyz.bytes.size() / (3 * sizeof(float));
  return json{{"frame_id", cloud.frame_id},
              {"frame", cloud.frame},
              {"npoints", cloud.npoints},
              {"shown", shown},
              {"src", blobs.Put("cloud", kPayloadsKept, std::move(xyz))}}
      .dump();
}

std::string CloudStatsEvent(const widestereo::cloud_stats_t& stats) {
  json stages = json::array();
  for (int i = 0; i < stats.nstages; ++i)
    stages.push_back({{"name", stats.stage_names[i]}, {"points", stats.stage_points[i]}, {"ms", stats.stage_ms[i]}});
  return json{{"frame_id", stats.frame_id},
              {"points", stats.nstages > 0 ? stats.stage_points.back() : 0},
              {"plane_found", stats.plane_found},
              {"plane_normal", stats.plane_normal},
              {"plane_offset", stats.plane_offset},
              {"inlier_rms", stats.inlier_rms},
              {"stages", stages}}
      .dump();
}

std::string HealthEvent(const widestereo::calibration_health_t& health) {
  return json{{"frame_id", health.frame_id},
              {"verdict", health.verdict},
              {"max_dy_px", health.max_dy_px},
              {"dy_median_px", Figure(health.dy_median_px)},
              {"dy_p95_px", Figure(health.dy_p95_px)},
              {"matches", health.matches},
              {"frames", health.frames},
              {"calibration", health.calibration}}
      .dump();
}

}  // namespace ws::view
