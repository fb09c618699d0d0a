#include "lcm_io/validate.h"

#include <algorithm>
#include <cmath>

#include "board/board_spec.h"
#include "lcm_io/camera_message_fields.h"
#include "lcm_io/image_codec.h"
#include "models/camera_ranges.h"

namespace ws {
namespace {

[[noreturn]] void Reject(const char* type, const std::string& what) {
  throw DecodeError(std::string(type) + ": " + what);
}

void Require(bool ok, const char* type, const std::string& what) {
  if (!ok) Reject(type, what);
}

template <class Range>
bool AllFinite(const Range& values) {
  return std::all_of(std::begin(values), std::end(values),
                     [](double v) { return std::isfinite(v); });
}

// A row-major 3x3 matrix with orthonormal rows and determinant +1, to 1e-6.
bool IsRotation(const double* R) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double dot = R[3 * i] * R[3 * j] + R[3 * i + 1] * R[3 * j + 1] + R[3 * i + 2] * R[3 * j + 2];
      if (!(std::abs(dot - (i == j)) <= 1e-6)) return false;
    }
  const double det = R[0] * (R[4] * R[8] - R[5] * R[7]) - R[1] * (R[3] * R[8] - R[5] * R[6]) +
                     R[2] * (R[3] * R[7] - R[4] * R[6]);
  return det > 0;
}

}  // namespace

void Validate(const widestereo::image_t& msg) { ValidateImage(msg); }

void Validate(const widestereo::stereo_frame_t& msg) {
  Validate(msg.left);
  if (!IsNoImage(msg.right)) Validate(msg.right);  // a one-camera rig sends no right image
}

void Validate(const widestereo::camera_corners_t& msg) {
  const char* t = "camera_corners_t";
  Require(msg.n >= 0, t, "negative corner count");
  if (msg.n == 0) return;
  Require(msg.image_width > 0 && msg.image_height > 0, t, "corners without an image size");
  // At most one point per corner of the board it names, each id on it: a
  // flood of points is no board (and would cost every solve).
  // A board of another tool's (imported corners) is bounded by kMaxCorners.
  constexpr int kMaxCorners = 10000;
  int corners = kMaxCorners;
  try {
    corners = std::min(corners, ParseBoardSpec(msg.board_id).corner_count());
  } catch (const std::invalid_argument&) {
  }
  Require(msg.n <= corners, t,
          std::to_string(msg.n) + " corners on a board of " + std::to_string(corners));
  for (int i = 0; i < msg.n; ++i) {
    const auto& p = msg.image_points[i];
    const auto& o = msg.object_points[i];
    Require(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(o[0]) &&
                std::isfinite(o[1]) && std::isfinite(o[2]),
            t, "corner " + std::to_string(i) + " is not finite");
    Require(msg.ids[i] >= 0 && msg.ids[i] < corners, t,
            "corner " + std::to_string(i) + " has id " + std::to_string(msg.ids[i]) + ", not on the board");
  }
  // Views are paired and compared corner by corner through the ids.
  std::vector<int32_t> ids(msg.ids.begin(), msg.ids.begin() + msg.n);
  std::sort(ids.begin(), ids.end());
  const auto repeated = std::adjacent_find(ids.begin(), ids.end());
  if (repeated != ids.end()) Require(false, t, "corner id " + std::to_string(*repeated) + " appears twice");
}

void Validate(const widestereo::stereo_corners_t& msg) {
  Validate(msg.left);
  Validate(msg.right);
}

void Validate(const widestereo::camera_calibration_t& msg) {
  try {
    CheckCameraRanges(CameraModelFields(msg));
  } catch (const std::invalid_argument& e) {
    Reject("camera_calibration_t", e.what());
  }
}

void Validate(const widestereo::stereo_calibration_t& msg) {
  const char* t = "stereo_calibration_t";
  Validate(msg.left);
  Validate(msg.right);
  Require(AllFinite(msg.R) && AllFinite(msg.T), t, "non-finite R or T");
  Require(IsRotation(msg.R), t, "R is not a rotation (R R^T = I, det R = 1)");
}

void Validate(const widestereo::calibration_status_t& msg) {
  Require(msg.grid_rows >= 0 && msg.grid_cols >= 0, "calibration_status_t", "negative grid size");
}

void Validate(const widestereo::calibration_health_t& msg) {
  const char* t = "calibration_health_t";
  Require(msg.verdict == "ok" || msg.verdict == "misaligned" || msg.verdict == "unknown", t,
          "unknown verdict '" + msg.verdict + "'");
  Require(msg.grid_rows >= 0 && msg.grid_cols >= 0, t, "negative grid size");
  Require(msg.matches >= 0 && msg.frames >= 0, t, "negative match or frame count");
  const double figures[] = {msg.max_dy_px, msg.dy_median_px, msg.dy_p95_px};
  Require(AllFinite(figures), t, "non-finite dy figures");
  for (const auto& row : msg.grid_dy_px) Require(AllFinite(row), t, "non-finite region dy");
  for (const auto& row : msg.grid_matches)
    Require(std::all_of(row.begin(), row.end(), [](int32_t n) { return n >= 0; }), t,
            "negative region match count");
}

void Validate(const widestereo::calibration_result_t& msg) {
  const char* t = "calibration_result_t";
  Require(msg.ncameras == 1 || msg.ncameras == 2, t, "one or two cameras");
  for (const auto& model : msg.models) {
    const double figures[] = {model.left_rms, model.left_heldout_rms, model.right_rms,
                              model.right_heldout_rms, model.stereo_rms};
    Require(AllFinite(figures), t, "non-finite RMS of model '" + model.model + "'");
  }
  for (const auto& camera : msg.cameras) {
    Require(ImageSizeAcceptable(camera.image_width, camera.image_height), t,
            "bad image size of camera '" + camera.name + "'");
    // A map is a handful of cells a side; more is no viewer's business.
    Require(camera.residual_rows >= 0 && camera.residual_cols >= 0 && camera.residual_rows <= 256 &&
                camera.residual_cols <= 256 && camera.uncertainty_rows >= 0 &&
                camera.uncertainty_cols >= 0 && camera.uncertainty_rows <= 256 &&
                camera.uncertainty_cols <= 256,
            t, "a map has 0 to 256 cells a side");
    for (const auto& row : camera.residual_rms_px) Require(AllFinite(row), t, "non-finite residual map");
    for (const auto& row : camera.uncertainty_px) Require(AllFinite(row), t, "non-finite uncertainty map");
  }
}

void Validate(const widestereo::calibration_views_t& msg) {
  const char* t = "calibration_views_t";
  for (int c = 0; c < 2; ++c)
    Require(msg.image_width[c] == 0 || ImageSizeAcceptable(msg.image_width[c], msg.image_height[c]), t,
            "bad image size");
  for (const auto& view : msg.views) {
    Require(view.left_corners >= 0 && view.right_corners >= 0, t, "negative corner count");
    const double rms[] = {view.left_rms, view.right_rms};
    Require(AllFinite(rms), t, "non-finite RMS of frame " + std::to_string(view.frame_id));
    for (const auto* outline : {&view.left_outline, &view.right_outline})
      for (const auto& point : *outline) Require(AllFinite(point), t, "non-finite outline");
  }
}

void Validate(const widestereo::disparity_t& msg) {
  Validate(msg.disparity);
  Require(msg.disparity.pixelformat == widestereo::image_t::PIXEL_FORMAT_FLOAT_GRAY32,
          "disparity_t", "disparity must be FLOAT_GRAY32");
  Require(msg.num_disparities > 0, "disparity_t", "num_disparities must be positive");
  Require(std::isfinite(msg.min_disparity), "disparity_t", "min_disparity must be finite");
  Require(msg.rectification == widestereo::disparity_t::RECTIFICATION_PINHOLE ||
              msg.rectification == widestereo::disparity_t::RECTIFICATION_LATLON,
          "disparity_t", "unknown rectification " + std::to_string(msg.rectification));
  Require(std::isfinite(msg.f) && msg.f > 0 && std::isfinite(msg.cx) && std::isfinite(msg.cy) &&
              std::isfinite(msg.baseline) && msg.baseline > 0,
          "disparity_t", "f and baseline must be positive, f, cx, cy, baseline finite");
}

void Validate(const widestereo::point_cloud_t& msg) {
  Require(msg.nintensity == 0 || msg.nintensity == msg.npoints, "point_cloud_t",
          "nintensity must be 0 or npoints");
}

void Validate(const widestereo::cloud_stats_t&) {}
void Validate(const widestereo::process_status_t& msg) {
  for (const auto& s : msg.stages)
    Require(s.count >= 0 && s.window >= 0 && s.window <= s.count && std::isfinite(s.median_ms) &&
                std::isfinite(s.p99_ms) && s.median_ms >= 0 && s.p99_ms >= s.median_ms,
            "process_status_t",
            "stage '" + s.stage + "': needs 0 <= window <= count and 0 <= median <= p99, all finite");
}
void Validate(const widestereo::command_t&) {}

}  // namespace ws
