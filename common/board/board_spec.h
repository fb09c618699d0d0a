// Calibration boards as the --board option names them, and their geometry.
//
//   chessboard:COLSxROWS:SQUARE
//   charuco:COLSxROWS:SQUARE:MARKER:DICT
//
// COLS x ROWS counts INNER corners for both types (a 9x6 board has 10x7
// squares), SQUARE and MARKER are side lengths in metres, and DICT is one of
// OpenCV's predefined ArUco dictionaries by name (DICT_4X4_50 ... DICT_7X7_1000,
// DICT_ARUCO_ORIGINAL, DICT_APRILTAG_16h5 ... DICT_APRILTAG_36h11). A ChArUco
// board is OpenCV's CharucoBoard of (COLS+1) x (ROWS+1) squares.
//
// Corner ids run row-major over the inner corners (id = row * COLS + col) and
// corner `id` lies at (col * SQUARE, row * SQUARE, 0) in the board frame, for
// both types; for ChArUco these are OpenCV's charuco corner ids.
#pragma once

#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace ws {

enum class BoardType { chessboard, charuco };

struct BoardSpec {
  std::string id;  // the spec string as given: the board_id of every corners message
  BoardType type = BoardType::chessboard;
  int cols = 0;  // inner corners per row
  int rows = 0;  // inner corner rows
  double square = 0;  // metres
  double marker = 0;  // metres, ChArUco only
  int dictionary = -1;  // cv::aruco::PREDEFINED_DICTIONARY_NAME, ChArUco only

  int corner_count() const { return cols * rows; }
  cv::Size pattern_size() const { return {cols, rows}; }
  // Board-frame position of corner `id`, metres.
  cv::Point3d ObjectPoint(int id) const;
};

// Parses a board spec as described above. Throws std::invalid_argument saying
// what is wrong and what a valid spec looks like.
BoardSpec ParseBoardSpec(const std::string& spec);

}  // namespace ws
