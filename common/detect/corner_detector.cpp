#include "detect/corner_detector.h"

#include <stdexcept>

#include "detect/charuco_detector.h"
#include "detect/chessboard_detectors.h"

namespace ws {

ChessboardMethod ParseChessboardMethod(const std::string& name) {
  if (name == "sb") return ChessboardMethod::sb;
  if (name == "classic") return ChessboardMethod::classic;
  throw std::invalid_argument("chessboard detector must be 'sb' or 'classic', not '" + name + "'");
}

const char* ChessboardMethodName(ChessboardMethod method) {
  return method == ChessboardMethod::sb ? "sb" : "classic";
}

std::unique_ptr<CornerDetector> MakeCornerDetector(const BoardSpec& board, ChessboardMethod method) {
  if (board.type == BoardType::charuco) return std::make_unique<CharucoDetector>(board);
  if (method == ChessboardMethod::sb) return std::make_unique<SbChessboardDetector>(board);
  return std::make_unique<ClassicChessboardDetector>(board);
}

}  // namespace ws
