#include "detect/corner_detector.h"

#include <stdexcept>

#include "detect/charuco_detector.h"
#include "detect/chessboard_detectors.h"

namespace ws {

ChessboardMethod ParseChessboardMethod(const std::string& name) {
  if (name == "sb") return ChessboardMethod::sb;
  if (name == "classic") return ChessboardMethod::classic;
  if (name == "opencv") return ChessboardMethod::opencv;
  throw std::invalid_argument("chessboard detector must be 'sb', 'classic' or 'opencv', not '" + name + "'");
}

const char* ChessboardMethodName(ChessboardMethod method) {
  switch (method) {
    case ChessboardMethod::sb: return "sb";
    case ChessboardMethod::classic: return "classic";
    case ChessboardMethod::opencv: return "opencv";
  }
  return "?";
}

std::unique_ptr<CornerDetector> MakeCornerDetector(const BoardSpec& board, ChessboardMethod method,
                                                   BoardSearch search) {
  if (board.type == BoardType::charuco) return std::make_unique<CharucoDetector>(board);
  if (method == ChessboardMethod::sb) return std::make_unique<SbChessboardDetector>(board);
  if (method == ChessboardMethod::opencv) return std::make_unique<OpenCvChessboardDetector>(board);
  return std::make_unique<ClassicChessboardDetector>(board, search);
}

}  // namespace ws
