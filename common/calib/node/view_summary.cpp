#include "calib/node/view_summary.h"

namespace ws::calib {
namespace {

// Fills `outline` with the image points of the board's four outermost corners seen.
void Outline(const widestereo::camera_corners_t& corners, float (&outline)[4][2]) {
  // Round the board: least x + y, most x - y, most x + y, least x - y.
  const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
  for (int k = 0; k < 4; ++k) {
    int best = -1;
    double best_score = 0;
    for (int i = 0; i < corners.n; ++i) {
      const double score = sx[k] * corners.object_points[i][0] + sy[k] * corners.object_points[i][1];
      if (best < 0 || score > best_score) best = i, best_score = score;
    }
    outline[k][0] = best < 0 ? 0.f : float(corners.image_points[best][0]);
    outline[k][1] = best < 0 ? 0.f : float(corners.image_points[best][1]);
  }
}

}  // namespace

widestereo::calibration_view_t ViewSummary(const widestereo::stereo_corners_t& msg) {
  widestereo::calibration_view_t view{};
  view.frame_id = msg.frame_id;
  view.frame_utime = msg.utime;
  view.left_corners = msg.left.n;
  view.right_corners = msg.right.n;
  Outline(msg.left, view.left_outline);
  Outline(msg.right, view.right_outline);
  view.left_rms = view.right_rms = -1;
  return view;
}

}  // namespace ws::calib
