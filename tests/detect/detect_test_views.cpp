#include "detect_test_views.h"

#include <cmath>

namespace ws::test {

std::vector<SyntheticView> SpreadOfViews(const BoardSpec& board, cv::Size size, int count) {
  std::vector<SyntheticView> views;
  for (int k = 0; k < count; ++k) {
    BoardPose pose;
    pose.roll_deg = -40 + 37 * k % 80;
    pose.tilt_x_deg = (k % 5 - 2) * 15;
    pose.tilt_y_deg = (k % 3 - 1) * 25;
    pose.fill = 0.45 + 0.05 * (k % 5);
    pose.shift = {0.04 * (k % 3 - 1), 0.04 * (k % 2 * 2 - 1)};
    RenderSettings settings;
    settings.size = size;
    settings.blur_sigma = 0.6 + 0.2 * (k % 4);
    settings.noise_sigma = 2;
    settings.seed = uint64_t(k + 1);
    views.push_back(RenderBoard(board, BoardToImage(board, pose, size), settings));
  }
  return views;
}

CornerErrors MeasureErrors(const CornerDetector& detector, const std::vector<SyntheticView>& views) {
  CornerErrors errors;
  double sum_squares = 0;
  for (const SyntheticView& view : views) {
    const BoardCorners found = detector.Detect(view.image);
    if (found.empty()) continue;
    errors.views_found++;
    for (size_t i = 0; i < found.ids.size(); ++i) {
      const cv::Point2d error = cv::Point2d(found.points[i]) - view.corners.at(size_t(found.ids[i]));
      sum_squares += error.dot(error);
      errors.corners++;
    }
  }
  errors.rms_px = errors.corners ? std::sqrt(sum_squares / errors.corners) : NAN;
  return errors;
}

}  // namespace ws::test
