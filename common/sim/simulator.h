// The built-in simulator: a stereo rig (sim_config.h) looking at a
// calibration board in a series of poses, then at a random-dot wall, then
// from inside a random-dot box room; renders
// each frame exactly through the lens models (render.h) and knows the ground
// truth of every frame (ground_truth.h).
//
//   Simulator sim(LoadSimConfig("config/sim/default.yaml"));
//   auto [left, right] = sim.Render(0);      // CV_8UC1, the cameras' image size
//   SimTruth truth = sim.Truth();            // cameras, R, T, poses, true corners
//
// Frames come in a fixed order, board poses first, then wall frames, then
// room frames; the
// same config (and seed) gives the same images, byte for byte.
#pragma once

#include <memory>
#include <utility>
#include <vector>

#include <opencv2/core.hpp>

#include "models/camera_model.h"
#include "sim/ground_truth.h"
#include "sim/ray_map.h"
#include "sim/render.h"
#include "sim/sim_config.h"

namespace ws {

struct SimFrame {
  enum class Kind { board, wall, room } kind = Kind::board;
  // The plane in the left camera's frame: its point (u, v, 0) is at R (u, v, 0) + t.
  cv::Matx33d R = cv::Matx33d::eye();
  cv::Vec3d t{0, 0, 1};
  int target_camera = 0;  // board frames: 0 left, 1 right
};

class Simulator {
 public:
  // Plans the board poses (throws SimConfigError when the board cannot be
  // placed inside the image) and builds each camera's ray map.
  explicit Simulator(SimConfig config);

  const SimConfig& config() const { return config_; }
  const std::vector<SimFrame>& frames() const { return frames_; }
  int frame_count() const { return int(frames_.size()); }
  const Camera& camera(int index) const { return index == 0 ? left_ : right_; }
  const RayMap& rays(int index) const { return index == 0 ? *left_rays_ : *right_rays_; }

  // The frame's plane in camera `index` (0 left, 1 right): X = R (u, v, 0) + t
  // (a room frame: the room's centre and axes).
  void PlaneInCamera(int frame, int index, cv::Matx33d* R, cv::Vec3d* t) const;

  // The frame's image in one camera: linear grey before blur and noise
  // (CV_32FC1), and the finished 8-bit image.
  cv::Mat RenderLinear(int frame, int index) const;
  cv::Mat RenderView(int frame, int index) const;
  std::pair<cv::Mat, cv::Mat> Render(int frame) const;

  // The truth of one frame and of all.
  SimFrameTruth FrameTruth(int frame) const;
  SimTruth Truth() const;

 private:
  SimViewTruth ViewTruth(int frame, int index) const;

  SimConfig config_;
  Camera left_, right_;
  std::shared_ptr<const RayMap> left_rays_, right_rays_;
  std::vector<SimFrame> frames_;
  std::unique_ptr<BoardPattern> board_front_, board_back_;
  std::unique_ptr<DotWallPattern> wall_;
  // The room's six faces in the left camera's frame (X = R (u, v, 0) + t,
  // the face's z axis pointing out of the room), each with its texture.
  std::vector<SimFrame> room_faces_;
  std::vector<std::unique_ptr<DotWallPattern>> room_patterns_;
};

}  // namespace ws
