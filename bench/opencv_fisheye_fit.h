// cv::fisheye::calibrate (Kannala-Brandt, 4 coefficients) as OpenCV's own
// samples call it (recomputed extrinsics, no skew) on one camera's views,
// and its K, D as the project's kb4 camera (the same model: kb4 is
// cv::fisheye's), so that its held-out error is measured as ours is.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <opencv2/calib3d.hpp>

#include "calib/solver/calib_data.h"
#include "models/camera_model.h"

namespace ws::bench {

struct OpenCvFisheyeFit {
  bool failed = false;
  std::string error;  // what cv::fisheye threw
  double rms_px = 0;  // cv::fisheye's RMS: per corner
  int views = 0, corners = 0;
  CameraModel kb4;
};

// The non-empty views of `data` that `take` accepts (all when it is empty).
inline OpenCvFisheyeFit FitOpenCvFisheye(const calib::CameraData& data,
                                         const std::function<bool(const calib::BoardView&)>& take = {}) {
  std::vector<std::vector<cv::Point3d>> object;
  std::vector<std::vector<cv::Point2d>> image;
  OpenCvFisheyeFit fit;
  for (const calib::BoardView& view : data.views) {
    if (view.empty() || (take && !take(view))) continue;
    object.emplace_back();
    image.emplace_back();
    for (int i = 0; i < view.size(); ++i) {
      object.back().emplace_back(view.object[i].x(), view.object[i].y(), view.object[i].z());
      image.back().emplace_back(view.image[i].x(), view.image[i].y());
    }
    fit.corners += view.size();
  }
  fit.views = static_cast<int>(object.size());
  cv::Matx33d K;
  cv::Vec4d D;
  std::vector<cv::Vec3d> rvecs, tvecs;
  try {
    fit.rms_px = cv::fisheye::calibrate(
        object, image, cv::Size(data.image_width, data.image_height), K, D, rvecs, tvecs,
        cv::fisheye::CALIB_RECOMPUTE_EXTRINSIC | cv::fisheye::CALIB_FIX_SKEW,
        cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 100, 1e-10));
  } catch (const cv::Exception& e) {
    fit.failed = true;
    fit.error = e.what();
    return fit;
  }
  fit.kb4.image_width = data.image_width;
  fit.kb4.image_height = data.image_height;
  fit.kb4.fx = K(0, 0);
  fit.kb4.fy = K(1, 1);
  fit.kb4.cx = K(0, 2);
  fit.kb4.cy = K(1, 2);
  fit.kb4.distortion = Distortion{ModelKind::kKb4, 0, {}, {D[0], D[1], D[2], D[3]}};
  return fit;
}

}  // namespace ws::bench
