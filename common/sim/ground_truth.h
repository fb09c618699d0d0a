// The simulator's ground truth: everything the images were made from, in a
// file that cv::FileStorage reads (YAML), and its loader.
//
// The file (one per simulator config; stereo-capture writes it when it opens
// a sim: source, see sim_source.h):
//
//   config: "config/sim/default.yaml"     seed: 1
//   cameras:                               # "left" then "right"
//     - { name: left, image_width, image_height, camera_matrix, model, degree, knots, alpha (or k),
//         p1, p2, nonradial,   # the calibration file's camera fields (rig/camera_fields.h)
//         field_deg: 200 }     # the lens's full field (sim_config.h; 360: no limit; optional when reading)
//   R: !!opencv-matrix, T: !!opencv-matrix     # X_right = R X_left + T (metres)
//   board: "chessboard:9x6:0.05"               # --board spec; "" without board frames
//   rendering: { supersample, blur_sigma, noise_sigma, black, white, background, gamma }
//   frames:
//     - { index: 0, kind: board, target: left,
//         R: !!opencv-matrix, t: !!opencv-matrix,      # board frame -> left camera
//         left:  { view: full|partial|none, corners: !!opencv-matrix (N x 2, u v for every id),
//                  in_image: [1, 1, 0, ...] },
//         right: { ... } }
//     - { index: 30, kind: wall, R, t,                 # wall frame -> left camera
//         wall_distance: 2.0, wall_normal: [nx, ny, nz], wall_offset: d }   # n . X = d
//     - { index: 31, kind: room, R, t,                 # room axes and centre -> left camera
//         room_planes: [nx, ny, nz, d, ...] }          # its six faces, n . X = d, n out of the room
//
// Corner pixels are projected through the camera models (pixel centres at
// integer coordinates). A corner is in_image when the lens images it (in
// front of a pinhole camera, within an angle model's field), it is on the
// side of the board the camera sees, and inside [0, W-1] x [0, H-1]. view is "full" when every corner is in the image and
// the whole board with its white margin is too (the board a chessboard
// detector should find), "partial" when some corners are, "none" otherwise.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "models/camera_model.h"
#include "rig/rig.h"
#include "sim/sim_config.h"

namespace ws {

enum class BoardView { full, partial, none };
const char* BoardViewName(BoardView view);

struct SimViewTruth {
  BoardView view = BoardView::none;
  std::vector<cv::Point2d> corners;  // one per board corner id
  std::vector<uint8_t> in_image;     // one per board corner id
};

struct SimFrameTruth {
  int index = 0;
  std::string kind;  // "board", "wall" or "room"
  cv::Matx33d R = cv::Matx33d::eye();  // plane frame -> left camera: X = R (u, v, 0) + t
  cv::Vec3d t{0, 0, 0};
  // board
  std::string target;  // the camera whose image the pose was aimed at: "left" / "right"
  SimViewTruth left, right;
  // wall
  double wall_distance = 0;
  cv::Vec3d wall_normal{0, 0, 1};
  double wall_offset = 0;
  // room: its six faces n . X = d (left camera frame, n out of the room, d > 0)
  std::vector<cv::Vec4d> room_planes;
};

struct SimTruth {
  std::string config;
  uint64_t seed = 0;
  Rig rig;  // the true cameras, R and T (no quality figures)
  std::array<double, 2> max_theta{M_PI, M_PI};  // each lens's half field (SimConfig::max_theta)
  std::string board;
  SimRendering rendering;
  std::vector<SimFrameTruth> frames;
};

// Throws std::runtime_error when the file cannot be written.
void WriteSimTruth(const std::string& path, const SimTruth& truth);
// Throws YamlFieldError (rig/yaml_reader.h) naming the file and the field
// that is missing or wrong.
SimTruth LoadSimTruth(const std::string& path);

}  // namespace ws
