// One corner order for a chessboard, whatever order a detector returned.
//
// A detector returns the COLS x ROWS grid row-major, but may start from any
// board corner: OpenCV's two detectors start from opposite ends of the same
// board. The physical board decides where it can:
//   1. handedness: rows run along +x and columns along +y of the image as seen
//      from the front (the board's z axis points away from the camera), so
//      (corner 1 - corner 0) x (corner COLS - corner 0) > 0 in image coordinates;
//   2. colour: the square between corners 0, 1, COLS and COLS+1 is dark.
//      This settles a board whose COLS + ROWS is odd (e.g. 9x6: 10x7 squares)
//      in every pose; it is the order findChessboardCorners gives the
//      opencv-doc images.
//   3. A board that looks the same turned 180 degrees (COLS + ROWS even) or
//      turned 90 degrees (COLS == ROWS) cannot say which end is which: corner
//      0 is then the candidate highest in the image (smallest y). Left and
//      right views of a level rig agree, but can disagree when the board is
//      held near the tie (its ends level in the image): use a board with
//      COLS + ROWS odd for stereo calibration.
#pragma once

#include <vector>

#include <opencv2/core.hpp>

namespace ws {

// Reorders a complete row-major grid of pattern.width x pattern.height
// corners found in `gray` (8-bit) into the order described above. Returns
// false, leaving them as they were, for a degenerate grid (no order has rows
// and columns spanning an area).
bool OrderChessboardCorners(const cv::Mat& gray, cv::Size pattern, std::vector<cv::Point2f>& corners);

}  // namespace ws
