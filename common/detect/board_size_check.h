// The board size a user gives is the commonest early mistake: squares
// counted instead of inner corners (10x7 for a 9x6 board), or one corner
// short (8x6 finds part of a 9x6 board, numbered from a different place in
// each image). These checks look for the sizes next to the one given.
#pragma once

#include <optional>
#include <vector>

#include <opencv2/core.hpp>

#include "board/board_spec.h"

namespace ws {

// The chessboard sizes next to `board` (one corner more or fewer per side,
// and the sizes in between), nearest first, none smaller than 3x3.
std::vector<cv::Size> NeighbourSizes(const BoardSpec& board);

// Whether OpenCV finds a chessboard of `size` inner corners in `gray` (8-bit).
bool ShowsChessboard(const cv::Mat& gray, cv::Size size);

// A larger chessboard than `board` that `gray` shows too, where `board` was
// found at `corners` (pixels): then `board` is part of the real one. Nothing
// for ChArUco. Looked for around the corners found, three squares beyond
// them each way (a larger board's extra row or column is one square away),
// not over the whole image: there findChessboardCorners searches for
// seconds (11 s a size at 1280 x 960) for a size it does not find.
std::optional<cv::Size> LargerBoardShown(const cv::Mat& gray, const BoardSpec& board,
                                         const std::vector<cv::Point2f>& corners);

// "chessboard:9x6:0.025": `board` with another size.
std::string WithSize(const BoardSpec& board, cv::Size size);

}  // namespace ws
