// A calibration board as an ideal pinhole camera sees it, rendered with the
// exact image position of every corner: ground truth for the detector tests
// and benchmarks until the project's simulator provides it.
//
// Rendering: every pixel averages supersample x supersample points of the
// board plane, mapped through the board-to-image homography (so edges are
// anti-aliased by area), lit unevenly if asked; then Gaussian blur (the
// lens) and Gaussian noise (the sensor), rounded to 8 bits. Pixel centres are at integer coordinates, as in
// OpenCV. Around the board is a white margin one square wide, then grey.
#pragma once

#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "board/board_spec.h"

namespace ws {

// Where the board is: turned about the optical axis (roll), tilted about the
// image's x and y axes, its centre moved by `shift` (fractions of the image
// size), at the distance where the board with its margin spans `fill` of the
// image width when seen head-on. The camera's focal length is the image width.
struct BoardPose {
  double roll_deg = 0;
  double tilt_x_deg = 0;
  double tilt_y_deg = 0;
  double fill = 0.6;
  cv::Point2d shift{0, 0};
};

struct RenderSettings {
  cv::Size size{640, 480};
  int supersample = 4;
  double blur_sigma = 0.7;   // pixels; 0: none
  double noise_sigma = 2.0;  // grey levels; 0: none
  // The light falls exponentially from the left edge of the image to the
  // right, where it is 1 / light_falloff as bright; 1: even light.
  double light_falloff = 1;
  uint64_t seed = 1;
};

struct SyntheticView {
  cv::Mat image;                     // CV_8UC1
  std::vector<cv::Point2d> corners;  // true image position of corner id i, for every id
};

// Board plane (metres, board frame of board_spec.h) to image pixels.
cv::Matx33d BoardToImage(const BoardSpec& board, const BoardPose& pose, cv::Size image_size);

SyntheticView RenderBoard(const BoardSpec& board, const cv::Matx33d& board_to_image,
                          const RenderSettings& settings);

}  // namespace ws
