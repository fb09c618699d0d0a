#include "board/board_spec.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <opencv2/aruco/dictionary.hpp>

namespace ws {
namespace {

constexpr const char* kUsage =
    "expected chessboard:COLSxROWS:SQUARE or charuco:COLSxROWS:SQUARE:MARKER:DICT "
    "(inner corners, metres), e.g. chessboard:9x6:0.025 or charuco:9x6:0.03:0.022:DICT_5X5_100";

// A square larger than this is a size in millimetres or centimetres.
constexpr double kMaxSquare = 0.5;

std::string Metres(double value) {
  std::ostringstream text;
  text << value << " m";
  return text.str();
}

[[noreturn]] void Fail(const std::string& spec, const std::string& why) {
  throw std::invalid_argument("board '" + spec + "': " + why + "; " + kUsage);
}

std::vector<std::string> Split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream stream(text);
  std::string part;
  while (std::getline(stream, part, separator)) parts.push_back(part);
  if (!text.empty() && text.back() == separator) parts.emplace_back();
  return parts;
}

int ParseCount(const std::string& spec, const std::string& text, const char* what) {
  size_t used = 0;
  int value = 0;
  try {
    value = std::stoi(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size()) Fail(spec, std::string(what) + " '" + text + "' is not a whole number");
  if (value < 3) Fail(spec, std::string(what) + " must be at least 3 inner corners, not " + text);
  return value;
}

double ParseLength(const std::string& spec, const std::string& text, const char* what) {
  size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size()) Fail(spec, std::string(what) + " '" + text + "' is not a number");
  if (!std::isfinite(value) || value <= 0)
    Fail(spec, std::string(what) + " must be a positive length in metres, not " + text);
  return value;
}

const std::vector<std::pair<std::string, int>>& DictionaryNames() {
  using namespace cv::aruco;
  static const std::vector<std::pair<std::string, int>> names = {
      {"DICT_4X4_50", DICT_4X4_50},           {"DICT_4X4_100", DICT_4X4_100},
      {"DICT_4X4_250", DICT_4X4_250},         {"DICT_4X4_1000", DICT_4X4_1000},
      {"DICT_5X5_50", DICT_5X5_50},           {"DICT_5X5_100", DICT_5X5_100},
      {"DICT_5X5_250", DICT_5X5_250},         {"DICT_5X5_1000", DICT_5X5_1000},
      {"DICT_6X6_50", DICT_6X6_50},           {"DICT_6X6_100", DICT_6X6_100},
      {"DICT_6X6_250", DICT_6X6_250},         {"DICT_6X6_1000", DICT_6X6_1000},
      {"DICT_7X7_50", DICT_7X7_50},           {"DICT_7X7_100", DICT_7X7_100},
      {"DICT_7X7_250", DICT_7X7_250},         {"DICT_7X7_1000", DICT_7X7_1000},
      {"DICT_ARUCO_ORIGINAL", DICT_ARUCO_ORIGINAL},
      {"DICT_APRILTAG_16h5", DICT_APRILTAG_16h5}, {"DICT_APRILTAG_25h9", DICT_APRILTAG_25h9},
      {"DICT_APRILTAG_36h10", DICT_APRILTAG_36h10}, {"DICT_APRILTAG_36h11", DICT_APRILTAG_36h11}};
  return names;
}

int ParseDictionary(const std::string& spec, const std::string& text) {
  for (const auto& [name, value] : DictionaryNames())
    if (name == text) return value;
  Fail(spec, "unknown ArUco dictionary '" + text + "' (OpenCV's names: DICT_4X4_50 ... DICT_7X7_1000, "
             "DICT_ARUCO_ORIGINAL, DICT_APRILTAG_16h5 ... DICT_APRILTAG_36h11)");
}

}  // namespace

cv::Point3d BoardSpec::ObjectPoint(int id) const {
  return {(id % cols) * square, (id / cols) * square, 0.0};
}

BoardSpec ParseBoardSpec(const std::string& spec) {
  const std::vector<std::string> fields = Split(spec, ':');
  BoardSpec board;
  board.id = spec;
  if (fields.empty() || (fields[0] != "chessboard" && fields[0] != "charuco"))
    Fail(spec, "unknown board type '" + (fields.empty() ? "" : fields[0]) + "'");
  board.type = fields[0] == "chessboard" ? BoardType::chessboard : BoardType::charuco;
  const size_t expected = board.type == BoardType::chessboard ? 3 : 5;
  if (fields.size() != expected)
    Fail(spec, fields[0] + " takes " + std::to_string(expected) + " ':'-separated fields, not " +
                   std::to_string(fields.size()));

  const std::vector<std::string> size = Split(fields[1], 'x');
  if (size.size() != 2) Fail(spec, "size '" + fields[1] + "' is not COLSxROWS");
  board.cols = ParseCount(spec, size[0], "COLS");
  board.rows = ParseCount(spec, size[1], "ROWS");
  board.square = ParseLength(spec, fields[2], "SQUARE");
  if (board.square > kMaxSquare)
    Fail(spec, "a " + fields[2] + " m square is larger than any hand-held board's (over " + Metres(kMaxSquare) +
                   "): is this in millimetres? SQUARE is in metres, 0.025 for 25 mm");
  if (board.type == BoardType::chessboard) return board;

  board.marker = ParseLength(spec, fields[3], "MARKER");
  if (board.marker >= board.square) Fail(spec, "MARKER must be smaller than SQUARE");
  board.dictionary = ParseDictionary(spec, fields[4]);
  const int markers = (board.cols + 1) * (board.rows + 1) / 2;
  const int available = cv::aruco::getPredefinedDictionary(board.dictionary)->bytesList.rows;
  if (markers > available)
    Fail(spec, "the board needs " + std::to_string(markers) + " markers but " + fields[4] +
                   " has " + std::to_string(available));
  return board;
}

}  // namespace ws
