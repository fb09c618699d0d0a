// bench_no_board: what a frame without a (whole) board costs the classic
// chessboard detector searching for every board (BoardSearch::kEveryBoard,
// stereo-calibrate --images), which tries every search before giving up
// (chessboard_detectors.cpp), against OpenCV's findChessboardCorners with its
// default flags alone, the detector's last search, in the same run; the
// difference is about what the live detector's (kFast) searches cost.
//
//   bench_no_board [--board chessboard:9x6:0.025]
// Frames: the opencv-doc scenes without a board (left.jpg, aloeL.jpg), a
// dark frame of sensor noise (a covered lens: mean 4, sigma 2 grey levels),
// and a rendered board half outside a 1280 x 960 image.
#include <cstdio>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>

#include "bench_support.h"
#include "detect/corner_detector.h"
#include "detect/synthetic_view.h"

namespace {

struct Frame {
  std::string name;
  cv::Mat gray;
};

std::vector<Frame> Frames(const ws::BoardSpec& board) {
  const std::string data = "/usr/share/doc/opencv-doc/examples/data/";
  std::vector<Frame> frames;
  for (const char* name : {"left.jpg", "aloeL.jpg"}) {
    const cv::Mat gray = cv::imread(data + name, cv::IMREAD_GRAYSCALE);
    if (gray.empty()) throw std::runtime_error("cannot read " + data + name + " (Debian's opencv-doc)");
    frames.push_back({std::string("opencv-doc ") + name, gray});
  }
  cv::Mat noise(503, 800, CV_32F), dark;
  cv::RNG(1).fill(noise, cv::RNG::NORMAL, 4, 2);
  noise.convertTo(dark, CV_8U);
  frames.push_back({"dark sensor noise", dark});
  ws::BoardPose pose;
  pose.fill = 0.8;
  pose.shift = {0.45, 0.1};
  const cv::Size size(1280, 960);
  ws::RenderSettings settings;
  settings.size = size;
  frames.push_back({"board half outside", ws::RenderBoard(board, ws::BoardToImage(board, pose, size), settings).image});
  return frames;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("Seconds the classic chessboard detector spends on frames without a whole board, against "
               "OpenCV's findChessboardCorners with its default flags.");
  std::string board_text = "chessboard:9x6:0.025";
  app.add_option("--board", board_text, "The chessboard (stereo-detect's --board)")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  try {
    const ws::BoardSpec board = ws::ParseBoardSpec(board_text);
    const auto classic = ws::MakeCornerDetector(board, ws::ChessboardMethod::classic, ws::BoardSearch::kEveryBoard);
    std::printf("%-22s %-10s %-12s %-26s %s\n", "frame", "size", "classic (s)", "OpenCV default flags (s)",
                "classic without it (s)");
    for (const Frame& frame : Frames(board)) {
      bool found = false;
      const double ours = 1e-3 * ws::bench::Milliseconds([&] { found = !classic->Detect(frame.gray).empty(); });
      std::vector<cv::Point2f> points;
      const double opencv = 1e-3 * ws::bench::Milliseconds(
                                       [&] { found |= cv::findChessboardCorners(frame.gray, board.pattern_size(), points); });
      if (found) throw std::runtime_error(frame.name + ": a board was found");
      std::printf("%-22s %4dx%-5d %-12.2f %-26.2f %.2f\n", frame.name.c_str(), frame.gray.cols, frame.gray.rows, ours,
                  opencv, ours - opencv);
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_no_board: %s\n", e.what());
    return 1;
  }
}
