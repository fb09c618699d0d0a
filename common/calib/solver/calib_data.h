// What calibration works on: the board corners one camera saw in one view,
// and the views of a stereo rig, aligned by index.
//
// A stereo data set holds the same number of views for both cameras; view j
// of the left and view j of the right come from the same stereo frame. A
// camera that did not see the board in a frame has an empty view there.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace ws::calib {

// Thrown for input no calibration can come from: too few views, degenerate
// (near-parallel) views, non-finite numbers where they cannot be skipped, a
// solver that did not converge to a valid camera. The message says which and
// what to do about it.
struct CalibrationError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The corners one camera saw in one view (one image).
struct BoardView {
  std::vector<int> ids;                 // corner ids on the board
  std::vector<Eigen::Vector3d> object;  // board frame, metres (z = 0 for a plane)
  std::vector<Eigen::Vector2d> image;   // pixels, (0, 0) the centre of the top-left pixel

  int size() const { return static_cast<int>(image.size()); }
  bool empty() const { return image.empty(); }
};

// All the views of one camera.
struct CameraData {
  std::string name;  // "left", "right"
  int image_width = 0;
  int image_height = 0;
  std::vector<BoardView> views;  // an empty view: the board was not seen
};

// Both cameras; left.views[j] and right.views[j] are stereo frame j.
struct StereoData {
  StereoData() {
    left.name = "left";
    right.name = "right";
  }
  CameraData left;
  CameraData right;

  int size() const { return static_cast<int>(left.views.size()); }
  void Add(const BoardView& left_view, const BoardView& right_view);
};

// Why a view cannot be used, or "" when it can: fewer than `min_points`
// corners, corners whose object points are (nearly) collinear, object points
// off the board plane z = 0, repeated ids. Non-finite corners are not a
// reason: CleanView drops them first.
std::string ViewProblem(const BoardView& view, int min_points = 6);

// Each corner's distance in the image (pixels) to its nearest neighbour on
// the board: the other corners of the view at the smallest board distance
// any two of them have (a grid's spacing); 0 for a corner with none there.
std::vector<double> NeighbourSpacing(const BoardView& view);

// The view without its non-finite corners (image or object point); the
// number dropped goes to *dropped.
BoardView CleanView(const BoardView& view, int* dropped);

}  // namespace ws::calib
