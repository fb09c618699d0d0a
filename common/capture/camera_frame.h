// One frame from one camera, and a stereo pair of them.
#pragma once

#include <cstdint>

#include <opencv2/core.hpp>

namespace ws {

struct CameraFrame {
  cv::Mat image;                    // owns its pixels: CV_8UC1, CV_16UC1 or CV_8UC3 (BGR)
  uint64_t frame_id = 0;            // the camera's block id (GigE Vision 1.x: 16 bits, wraps)
  int64_t camera_timestamp_ns = 0;  // the camera's clock
  int64_t host_timestamp_ns = 0;    // this host's wall clock when the frame began to arrive
};

struct StereoFrame {
  CameraFrame left;
  CameraFrame right;
};

enum class Side { left, right };

}  // namespace ws
