// Epipolar accuracy as users see it: stereo-match --save-rectified writes
// the rectified pairs of a log, the board detector finds the board in each
// saved image, and corresponding corners should share a row. What is
// measured is the row difference of every corner found in both images of a
// pair (rectified rows: the calibration's epipolar error plus the
// detector's noise, in rectified pixels).
#pragma once

#include <string>

#include "detect/board_spec.h"
#include "rectify/rectification.h"

namespace ws::test {

struct BoardRows {
  int pairs = 0;    // saved pairs
  int boards = 0;   // pairs with the whole board found in both images
  int corners = 0;  // corner pairs measured
  double rms = 0;   // row difference, px
  double median = 0;  // |row difference|, px
};

// stereo-match --calib CALIB --rectification MODE --save-rectified OUT_DIR
// over IMAGES (a log of STEREO_IMAGES), then the board in every saved pair.
// A board symmetric under a half turn may be numbered from opposite ends in
// the two images: the pairing with the smaller row differences is kept.
BoardRows MeasureRectifiedBoardRows(const std::string& images, const std::string& calib,
                                    RectificationMode mode, const std::string& out_dir,
                                    const BoardSpec& board);

void PrintBoardRows(const char* what, RectificationMode mode, const BoardRows& rows);

}  // namespace ws::test
