// Board specs: both types parse, every malformed one is a clear error, and
// object points follow the ids.
#include <gtest/gtest.h>

#include "board/board_spec.h"

namespace {

using ws::BoardType;
using ws::ParseBoardSpec;

TEST(BoardSpec, ParsesAChessboard) {
  const auto board = ParseBoardSpec("chessboard:9x6:0.025");
  EXPECT_EQ(board.type, BoardType::chessboard);
  EXPECT_EQ(board.id, "chessboard:9x6:0.025");
  EXPECT_EQ(board.cols, 9);
  EXPECT_EQ(board.rows, 6);
  EXPECT_DOUBLE_EQ(board.square, 0.025);
  EXPECT_EQ(board.corner_count(), 54);
}

TEST(BoardSpec, ParsesACharucoBoard) {
  const auto board = ParseBoardSpec("charuco:11x8:0.03:0.022:DICT_5X5_100");
  EXPECT_EQ(board.type, BoardType::charuco);
  EXPECT_EQ(board.cols, 11);
  EXPECT_EQ(board.rows, 8);
  EXPECT_DOUBLE_EQ(board.marker, 0.022);
  EXPECT_GE(board.dictionary, 0);
}

TEST(BoardSpec, ObjectPointsAreRowMajorInMetresOnThePlaneZ0) {
  const auto board = ParseBoardSpec("chessboard:9x6:0.025");
  EXPECT_EQ(board.ObjectPoint(0), cv::Point3d(0, 0, 0));
  EXPECT_EQ(board.ObjectPoint(1), cv::Point3d(0.025, 0, 0));
  EXPECT_EQ(board.ObjectPoint(9), cv::Point3d(0, 0.025, 0));
  EXPECT_NEAR(board.ObjectPoint(53).x, 0.2, 1e-12);
  EXPECT_NEAR(board.ObjectPoint(53).y, 0.125, 1e-12);
}

void ExpectError(const std::string& spec, const std::string& says) {
  try {
    ParseBoardSpec(spec);
    ADD_FAILURE() << spec << " parsed";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(says), std::string::npos) << spec << ": " << what;
    EXPECT_NE(what.find("chessboard:COLSxROWS:SQUARE"), std::string::npos) << what;  // the usage
  }
}

TEST(BoardSpec, MalformedSpecsSayWhatIsWrong) {
  ExpectError("", "unknown board type ''");
  ExpectError("circles:4x11:0.02", "unknown board type 'circles'");
  ExpectError("chessboard:9x6", "takes 3 ':'-separated fields, not 2");
  ExpectError("chessboard:9x6:0.025:extra", "takes 3");
  ExpectError("chessboard:9-6:0.025", "is not COLSxROWS");
  ExpectError("chessboard:9x6x2:0.025", "is not COLSxROWS");
  ExpectError("chessboard:nx6:0.025", "COLS 'n' is not a whole number");
  ExpectError("chessboard:9x6.5:0.025", "ROWS '6.5' is not a whole number");
  ExpectError("chessboard:2x6:0.025", "at least 3 inner corners");
  ExpectError("chessboard:9x6:abc", "SQUARE 'abc' is not a number");
  ExpectError("chessboard:9x6:-0.02", "positive length");
  ExpectError("chessboard:9x6:nan", "positive length");
  ExpectError("charuco:9x6:0.03:0.022", "takes 5");
  ExpectError("charuco:9x6:0.03:0.04:DICT_5X5_100", "MARKER must be smaller than SQUARE");
  ExpectError("charuco:9x6:0.03:0.022:DICT_9X9_1", "unknown ArUco dictionary 'DICT_9X9_1'");
  ExpectError("charuco:19x14:0.03:0.022:DICT_4X4_50", "needs 150 markers but DICT_4X4_50 has 50");
}

}  // namespace
