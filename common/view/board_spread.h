// How well the boards found so far spread over what a calibration needs, as
// ROS camera_calibration measures it (image_pipeline's calibrator.py): each
// board in the left image gives four measures in [0, 1],
//  - x, y: where the centre of its corners sits across and down, its own
//    extent (the square root of its outline's area) taken off the image's;
//  - size: the square root of its outline's area over the image's;
//  - skew: how far the angle at its outline's top-right corner is from a
//    right angle, twice that in radians, at most 1;
// and a board is kept when it differs from every kept one by more than 0.2
// (the sum of the four measures' differences). Each measure's bar is the
// range the kept boards cover over the range wanted (0.7, 0.7, 0.4, 0.5);
// enough is every bar full, or kEnoughBoards kept.
#pragma once

#include <array>
#include <optional>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "widestereo/camera_corners_t.hpp"

namespace ws::view {

using BoardMeasures = std::array<double, 4>;  // x, y, size, skew

// The measures of one camera's corners; none with fewer than 4 corners or
// an outline of no area. The outline is the corners nearest the board's
// four extreme corners (by their object points), so a partial board counts.
std::optional<BoardMeasures> MeasureBoard(const widestereo::camera_corners_t& corners);

class BoardSpread {
 public:
  static constexpr int kEnoughBoards = 40;
  static constexpr size_t kMaxBoards = 1000;  // bounds what a peer sending corners can make it keep
  static constexpr std::array<double, 4> kWantedRange = {0.7, 0.7, 0.4, 0.5};

  // Keeps `m` unless a kept board is within 0.2 of it or kMaxBoards are
  // kept; whether it was kept.
  bool Add(const BoardMeasures& m);
  void Clear() { kept_.clear(); }
  // Each bar's progress in [0, 1] (all 0 before any board).
  std::array<double, 4> Progress() const;
  bool Enough() const;
  // {"boards": N, "bars": [{"name", "low", "high", "progress"}...], "enough": B}
  nlohmann::json Json() const;

 private:
  // Each measure's lowest and highest over the kept boards.
  std::array<std::pair<double, double>, 4> Ranges() const;

  std::vector<BoardMeasures> kept_;
};

}  // namespace ws::view
