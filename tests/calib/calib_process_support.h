// Running the capture -> detect -> calibrate chain as real processes, log to
// log, for the stereo-calibrate tests.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "calib/solver/calib_data.h"
#include "test_support.h"

namespace ws::calib::test {

std::string FileUrl(const std::string& path, const std::string& mode);

// stereo-capture --source SOURCE [extra] into DIR/images.lcmlog, then
// stereo-detect --board BOARD into DIR/corners.lcmlog; returns the corners
// log (test failures when a stage fails).
std::string CaptureAndDetect(const std::string& dir, const std::string& source,
                             const std::string& board, const std::vector<std::string>& extra = {});

// stereo-calibrate --once over the corners log with `extra` options, its
// output log, --out and --report in DIR/NAME.{lcmlog,yaml,json}.
ws::test::CommandResult CalibrateOnce(const std::string& dir, const std::string& corners,
                                      const std::string& name, std::vector<std::string> extra);

// The STEREO_CORNERS of a log as calibration data.
StereoData ReadCorners(const std::string& corners_log);

nlohmann::json ReadJson(const std::string& path);

// One camera's non-empty views as OpenCV's calibration input (Point3f /
// Point2f for cv::calibrateCamera, Point3d / Point2d for cv::fisheye).
template <class ObjectPoint, class ImagePoint>
void OpenCvViews(const CameraData& camera, std::vector<std::vector<ObjectPoint>>* object,
                 std::vector<std::vector<ImagePoint>>* image) {
  for (const BoardView& view : camera.views) {
    if (view.empty()) continue;
    object->emplace_back();
    image->emplace_back();
    for (int i = 0; i < view.size(); ++i) {
      object->back().emplace_back(view.object[i].x(), view.object[i].y(), view.object[i].z());
      image->back().emplace_back(view.image[i].x(), view.image[i].y());
    }
  }
}

}  // namespace ws::calib::test
