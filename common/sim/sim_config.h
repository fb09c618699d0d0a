// The simulator's configuration (stereo-capture --source sim:CONFIG.yaml):
// a stereo rig through any lens model, the scenes it looks at, how the
// images are rendered. config/sim/default.yaml documents every field.
//
//   seed: 1                       # poses, wall texture and noise follow from it
//   truth: PATH                   # optional: where the ground truth goes
//   rig:
//     baseline: 0.3               # metres; the right camera sits at +baseline on the left x axis
//     rotation_deg: [0, 0, 0]     # optional: the right camera's rotation (rotation vector, degrees)
//     # or  T: [-0.3, 0, 0]       # instead of baseline:  X_right = R X_left + T
//     left:  {lens: ..., image_size: [1280, 960], ...}    (see SimCameraFields below)
//     right: {...}                # optional: the same camera as left
//   scene:
//     board: {spec: chessboard:9x6:0.05, poses: 30, ...}  # optional
//     wall:  {frames: 5, distance: 2.0, ...}              # optional
//     room:  {frames: 1, size: [4, 3, 4], centre: [0, 0, 0], ...}  # optional (one scene at least)
//   rendering: {supersample: 4, blur_sigma: 0.6, noise_sigma: 1.0, ...}
//
// Camera fields:
//   lens: theia | fisheye-knee | table:PATH | table-percent:PATH | poly6:k1,k2,k3 | poly12:k1,...,k6
//     theia    the Theia-MY125M-like design table compiled into the library
//     fisheye-knee  the 200-degree bspline_theta lens of models/fisheye_lens.h
//              (1280 x 960, f = 300 px; its own image size and focal length:
//              only fx, fy, cx, cy may change it), field_deg 200 by default
//     table    a lens-design table (lens_table.h, heights in mm; PATH relative
//              to the config file's folder), fitted with `fit`
//     polyN    explicit coefficients on the normalized radius
//   fit: bspline | poly6 | poly12    table lenses: the model fitted to the table (default bspline)
//   focal_length_mm: 1.3, pixel_pitch_mm: 0.00375   fx = fy = focal / pitch
//   image_size: [W, H]                              (default 1280 x 960)
//   fx, fy, cx, cy: override (pixels; cx, cy default to W/2, H/2)
//   p1, p2: tangential distortion (default 0)
//   sensor_tilt_deg: [tau_x, tau_y]   the sensor tilted in its mount
//              (models/sensor_tilt.h, OpenCV's tilted model; default none, at
//              most 5 degrees)
//   field_deg: the lens's full field (degrees): rays farther than half of it
//              off axis are not imaged, the pixels past its image circle are
//              black (default: no limit; pinhole models see less than 180)
//
// Every field is checked; an unknown field, a missing required one or a bad
// value throws SimConfigError naming the file, the field and the reason:
//   "config/sim/x.yaml: rendering.supersample: must be a whole number from 1 to 16, not 0"
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

#include <opencv2/core.hpp>

#include "board/board_spec.h"
#include "models/camera_model.h"

namespace ws {

struct SimConfigError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Board frames: a calibration board held in front of the rig, one pose per
// frame. Each pose aims the board's centre at a target position in one
// camera's image: a grid of grid_cols x grid_rows positions spanning the whole
// image, corners included (jittered by up to a quarter cell), for each camera
// in turn (targets "both") or one camera; for a lens with an image circle
// (field_deg) the grid spans the circle's bounding box within the image. The
// board starts at a random depth (along the optical axis; for an angle model,
// the distance to the board's centre, which may be behind the image plane),
// turned a third of the way (an angle model: 70 %) from parallel to the
// image plane towards facing the camera, and is tilted and rolled at random,
// never so far that either camera sees it more obliquely than 60 degrees.
// Then it slides from the image centre towards its target until it touches
// the image border with edge_margin_px to spare, or the image circle (its
// squares and white margin inside the aimed camera's image); it is pushed back (up to
// depth_max) only when it is too large for the image. The other camera may
// see the board only in part (the ground truth says so).
struct SimBoardScene {
  BoardSpec board;                  // detect/board_spec.h; the board has a white margin one square wide
  int poses = 30;
  double depth_min = 0.4, depth_max = 1.1;  // metres (see above)
  double max_tilt_deg = 35;         // tilt of the board plane from parallel to the image plane
  double max_roll_deg = 20;         // turn about the board normal
  int grid_cols = 5, grid_rows = 3;
  enum class Targets { both, left, right } targets = Targets::both;
  // Pixels between the board (squares and white margin) and the image
  // border; negative: the board may run that far off the image (partial
  // ChArUco views).
  double edge_margin_px = 4;
};

// Wall frames: a flat wall covered with a random-dot texture (square dots of
// dot_size on a grid, each dark with probability `density`, the rest light),
// `distance` metres in front of the left camera, perpendicular to its optical
// axis unless tilted (about the left camera's x then y axis). The wall does
// not move; each frame has fresh noise.
struct SimWallScene {
  int frames = 5;
  double distance = 2.0;
  double tilt_x_deg = 0, tilt_y_deg = 0;
  double dot_size = 0.02;  // metres
  double density = 0.5;
};

// Room frames: the rig inside a box room, axis-aligned with the left
// camera, its six faces covered with random-dot textures (each face its own,
// like the wall's). `centre` is the box's centre in the left camera's frame;
// both cameras must be inside. Every ray meets exactly one face (the first
// the ray leaves the box through), so a lens of any field, beyond 180
// degrees too, sees texture everywhere.
struct SimRoomScene {
  int frames = 1;
  cv::Vec3d size{4, 3, 4};    // metres along x (width), y (height, down), z (depth)
  cv::Vec3d centre{0, 0, 0};  // metres, left camera frame
  double dot_size = 0.02;     // metres
  double density = 0.5;
};

// From the scene to 8-bit pixels. Grey levels are those of the sensor before
// gamma: black and white parts of the scene, and the background around the
// board. Each pixel averages supersample x supersample points of the scene
// (only pixels where the scene is not uniform are supersampled: exact, as the
// pattern's regions are convex), then Gaussian blur (the optics), gamma
// (out = 255 (v / 255)^(1 / gamma)), Gaussian noise (the sensor), rounding to 8 bits.
struct SimRendering {
  int supersample = 4;
  double blur_sigma = 0.6;   // pixels; 0: none
  double noise_sigma = 1.0;  // grey levels; 0: none
  double black = 30, white = 220, background = 128;
  double gamma = 1.0;
};

struct SimConfig {
  std::string source;  // the file it came from, for messages and labels ("" when built in code)
  uint64_t seed = 1;
  CameraModel left, right;
  // Each lens's half field (radians, left then right): rays farther off axis
  // are not imaged (field_deg / 2; pi: no limit).
  std::array<double, 2> max_theta{M_PI, M_PI};
  cv::Matx33d R = cv::Matx33d::eye();  // X_right = R X_left + T
  cv::Vec3d T{-0.3, 0, 0};
  std::optional<SimBoardScene> board;
  std::optional<SimWallScene> wall;
  std::optional<SimRoomScene> room;
  SimRendering rendering;
  std::string truth_path;  // from `truth:` (relative to the working folder); "" when not given
};

// Reads and checks a simulator config. Throws SimConfigError.
SimConfig LoadSimConfig(const std::string& path);
// The same from YAML text; `source` names it in messages and `base_dir`
// resolves relative table paths.
SimConfig ParseSimConfig(const std::string& yaml, const std::string& source,
                         const std::string& base_dir);

// The camera the simulator uses by default: the Theia-like table fitted as a
// B-spline (TheiaLikeCamera()), optionally scaled to a smaller image with
// the same field of view (scale 0.5: 640 x 480, fx halved).
CameraModel SimDefaultCamera(double scale = 1.0);

// A rig of two default cameras 0.3 m apart with a 9x6 chessboard and the wall,
// at full resolution or scaled: what tests start from.
SimConfig DefaultSimConfig(double scale = 1.0);

}  // namespace ws
