// Epipolar accuracy as users see it: stereo-match --save-rectified writes
// the rectified pairs of a log, the board detector finds the board in each
// saved image, and corresponding corners should share a row. What is
// measured is the row difference of every corner found in both images of a
// pair (rectified rows: the calibration's epipolar error plus the
// detector's noise, in rectified pixels).
#pragma once

#include <cstdint>
#include <string>

#include "board/board_spec.h"
#include "rectify/rectification.h"

namespace ws::test {

struct BoardRows {
  int pairs = 0;    // saved pairs
  int boards = 0;   // pairs with the whole board found in both images
  int corners = 0;  // corner pairs measured
  double rms = 0;   // row difference, px
  double median = 0;  // |row difference|, px
  // The same for the corners whose rays (left and right) are within 60
  // degrees of the epipolar planes' common normal: nearer the epipoles a
  // lat-lon row spans cos(psi) times the angle of a central row, so a
  // corner's detection error grows in rows by 1 / cos(psi).
  int central_corners = 0;
  double central_rms = 0;
  // Per pair with a board: its mean row difference (a pair not taken at one
  // instant, a hand-held rig not triggered together, is off by a row shift
  // of its own) and the RMS about that mean (the scatter); the median
  // scatter over the pairs, the largest and its pair, the largest shift.
  double pair_scatter_median = 0, largest_scatter = 0, largest_shift = 0;
  int64_t largest_scatter_pair = -1;
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
