// Measuring a reconstructed box room (the simulator's room scene) against
// its truth. Both rectification modes share the rectified frame (Bouguet's
// rotations), so every cloud is measured on one grid: the lat-lon image of
// the common field both lenses see, where a pinhole rectification holds
// only the central part.
#pragma once

#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "cloud/cloud_filter_config.h"
#include "rectify/rectification.h"
#include "rig/rig.h"
#include "widestereo/point_cloud_t.hpp"

namespace ws::test {

struct RoomField {
  Rectification latlon;            // of the true rig: the common field's grid
  std::vector<cv::Vec4d> planes;   // the room's faces n . X = d in the rectified frame
  cv::Mat disparity;               // true lat-lon disparity where both lenses see a face, else 0
  cv::Mat face;                    // CV_32SC1: the face seen there, else -1
};

// `planes`: SimFrameTruth::room_planes (left camera frame).
RoomField TrueRoomField(const Rig& rig, const std::vector<cv::Vec4d>& planes);

struct FaceFit {
  double field_fraction = 0;  // of the common field (cells), the part showing this face
  int points = 0;             // cloud points whose ray meets this face first
  bool found = false;         // stereo-cloud's plane fit on them found a plane
  double offset = 0, true_offset = 0;  // the camera's distance to the fitted / true plane, metres
  double tilt_rad = 0, inlier_rms = 0;
};

struct RoomFit {
  // Of the common field's cell x cell cells, those holding a point whose
  // lat-lon disparity is within 1 px of the truth's.
  double coverage = 0;
  std::vector<FaceFit> faces;  // one per plane
};

// Each face's points (by the face their ray meets first) through
// stereo-cloud's plane fit (CloudFilter: the plane stage of `config` alone).
RoomFit MeasureRoom(const widestereo::point_cloud_t& cloud, const RoomField& field,
                    const CloudFilterConfig& config, int cell = 8);

// "right (+x)", "floor (+y)", ... from a face's normal in the left camera frame.
std::string FaceName(const cv::Vec4d& plane);

}  // namespace ws::test
