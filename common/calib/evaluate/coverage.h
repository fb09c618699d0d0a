// Where the board has been: corners per image cell for each camera, and a
// hint for the person holding the board. The paper's own calibration failed
// where the image periphery had no corners, so the hint names the empty
// regions, the corners and edges first.
//
// Also the near-duplicate test stereo-calibrate uses to skip views it
// already has (a person holding a board still gives many equal frames).
#pragma once

#include <string>
#include <vector>

#include "calib/solver/calib_data.h"

namespace ws::calib {

struct CoverageGrid {
  int rows = 6, cols = 8;
  int image_width = 0, image_height = 0;
  std::vector<int> count;  // row-major

  CoverageGrid() = default;
  CoverageGrid(int rows, int cols);
  void Add(const BoardView& view, int image_width, int image_height);
  // 3 x 3 regions: "top-left corner", "top edge", ..., "centre"; cells in the
  // outer ring of the grid belong to the edges and corners.
  std::vector<std::string> EmptyRegions() const;
};

struct CoverageStatus {
  int views_left = 0, views_right = 0, views_stereo = 0;
  CoverageGrid left, right;
};

// The hint for the person holding the board: what is missing, most
// important first (too few views, no stereo views, empty regions of either
// image), or that coverage is complete and a solve can be asked for.
std::string CoverageHint(const CoverageStatus& status, int min_views);

// True when `candidate` shows the board where `existing` does: at least 80 %
// of the corners in common, and their mean image distance below
// `threshold_px` (or equal to it: a threshold of 0 takes only the same
// corners). Two empty views are duplicates; an empty and a non-empty
// view are not.
bool NearDuplicate(const BoardView& candidate, const BoardView& existing, double threshold_px);

}  // namespace ws::calib
