// Rendering a textured plane through a camera's ray map, exactly.
//
// The plane carries a pattern: a grey level at every point (u, v) of the
// plane (metres, in the plane's own frame) and the id of the region the point
// lies in. Regions are convex and of one grey level each (a chessboard
// square, a marker cell, a wall dot, ...).
//
// For every pixel the four corner rays are intersected with the plane (the
// plane-to-camera homography H maps (u, v, 1) to a camera-frame point, so a
// ray r meets the plane at (p0 / p2, p1 / p2) with p = H^-1 r, ahead along
// the ray when p2 > 0: rays beyond 90 degrees too). When all four corners lie in one region the pixel
// is that region's grey level: the pixel's footprint lies in the convex hull
// of its corners' hits, so in the region. Otherwise the pixel averages
// supersample x supersample points at the centres of a regular grid of
// sub-pixels, each at the ray interpolated bilinearly from the corners,
// unless the pattern says it is uniform over the bounding box of the corners'
// hits (which holds every sub-pixel's hit too).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <opencv2/core.hpp>

#include "board/board_spec.h"
#include "sim/ray_map.h"
#include "sim/sim_config.h"

namespace ws {

struct PatternSample {
  float value = 0;   // linear grey level, 0..255
  int64_t region = 0;
};

class PlanePattern {
 public:
  virtual ~PlanePattern() = default;
  virtual PatternSample At(double u, double v) const = 0;
  // What a ray that does not meet the plane in front of the camera sees.
  virtual PatternSample Miss() const = 0;
  // True, with the grey level, when the pattern is one grey level over all
  // of [u0, u1] x [v0, v1]; false when it may not be (the default).
  virtual bool Uniform(double u0, double u1, double v0, double v1, float* value) const {
    (void)u0, (void)u1, (void)v0, (void)v1, (void)value;
    return false;
  }
};

// A calibration board (board_spec.h frame: corner id at (col, row) * square)
// with a white margin one square wide, on the background grey. Chessboards
// are analytic; ChArUco boards too, from OpenCV's board layout (marker
// positions, ids and bits), so the markers are exact. Seen from behind
// (front = false) the board is plain white.
class BoardPattern final : public PlanePattern {
 public:
  BoardPattern(const BoardSpec& board, const SimRendering& levels, bool front = true);
  PatternSample At(double u, double v) const override;
  PatternSample Miss() const override;

 private:
  struct Marker {
    int bits_per_side = 0;
    cv::Mat bits;          // CV_8UC1, 1 = white
    cv::Vec2d origin;      // marker corner 0 in square units from the board's outer corner
    cv::Vec2d axis_x, axis_y;  // unit vectors along its rows and columns (board axes)
    double side = 0;       // marker side, in squares
  };
  BoardSpec board_;
  float black_, white_, background_;
  bool front_;
  double inverse_square_;
  int squares_x_, squares_y_;
  std::vector<int> marker_of_square_;  // squares_x * squares_y, -1: none
  std::vector<Marker> markers_;
};

// A random-dot texture: a grid of square dots of `dot_size` metres, each dark
// with probability `density` (from a hash of the seed and the dot's indices),
// else light; the plane is unbounded.
class DotWallPattern final : public PlanePattern {
 public:
  DotWallPattern(double dot_size, double density, uint64_t seed, const SimRendering& levels);
  PatternSample At(double u, double v) const override;
  PatternSample Miss() const override;
  // The dots the rectangle touches (up to 3 x 3) are all dark or all light.
  bool Uniform(double u0, double u1, double v0, double v1, float* value) const override;

 private:
  bool Dark(int64_t iu, int64_t iv) const;

  double inverse_size_;
  uint64_t threshold_, seed_;
  float black_, white_, background_;
};

// The linear grey image (CV_32FC1, the ray map's size) of the plane whose
// points (u, v, 0) map to camera points by `plane_to_camera` (H = [r1 r2 t]).
// Pixels next to a ray the lens cannot give (past a fisheye's image circle)
// are 0.
cv::Mat RenderPlane(const RayMap& rays, const cv::Matx33d& plane_to_camera, const PlanePattern& pattern,
                    int supersample);

// The linear grey image of the inside of a convex box of textured faces, the
// camera inside: each ray sees the face it leaves the box through, the
// nearest of the faces' planes ahead along it (face k's points (u, v, 0) map
// to camera points by faces_to_camera[k]).
cv::Mat RenderRoom(const RayMap& rays, const std::vector<cv::Matx33d>& faces_to_camera,
                   const std::vector<const DotWallPattern*>& patterns, int supersample);

// Optics and sensor: Gaussian blur, gamma, Gaussian noise from `noise_seed`,
// rounding to CV_8UC1.
cv::Mat FinishImage(const cv::Mat& linear, const SimRendering& rendering, uint64_t noise_seed);

// A 64-bit mix of the values (splitmix64 steps): seeds for noise and dots.
uint64_t MixSeed(std::initializer_list<uint64_t> values);

}  // namespace ws
