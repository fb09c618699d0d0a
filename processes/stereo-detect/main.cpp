// stereo-detect: finds the calibration board in both images of every stereo
// pair on STEREO_IMAGES and publishes the corners on STEREO_CORNERS, in order,
// on several threads.
#include <algorithm>
#include <cstdio>
#include <thread>

#include "detect/corner_stage.h"
#include "runtime/max_image_pixels_option.h"
#include "runtime/process.h"
#include "runtime/process_cli.h"

int main(int argc, char** argv) {
  ws::ProcessCli cli("stereo-detect",
                     "Finds the calibration board in both images of every pair on STEREO_IMAGES and "
                     "publishes its corners (ids, image and object points) on STEREO_CORNERS.");
  std::string board = "chessboard:9x6:0.025";
  std::string chessboard_detector = ws::ChessboardMethodName(ws::kDefaultChessboardMethod);
  int workers = std::max(1, int(std::thread::hardware_concurrency()));
  int max_in_flight = 4;
  auto& app = cli.app();
  app.add_option("--board", board,
                 "chessboard:COLSxROWS:SQUARE or charuco:COLSxROWS:SQUARE:MARKER:DICT "
                 "(inner corners, metres; DICT an OpenCV ArUco dictionary, e.g. DICT_5X5_100)")
      ->capture_default_str();
  app.add_option("--chessboard-detector", chessboard_detector,
                 "sb (findChessboardCornersSB) or classic (findChessboardCorners + cornerSubPix), both "
                 "then refined to saddle points; or opencv (OpenCV's own findChessboardCorners with "
                 "adaptive threshold + cornerSubPix, no more: for comparison)")
      ->check(CLI::IsMember({"sb", "classic", "opencv"}))
      ->capture_default_str();
  app.add_option("--workers", workers, "Detection threads (default: one per core)")->check(CLI::Range(1, 256));
  app.add_option("--max-in-flight", max_in_flight,
                 "Frames held at once, waiting or being detected; live, frames beyond are dropped "
                 "and counted (replaying a log, the input waits). More workers than this stay idle")
      ->check(CLI::Range(1, 1024))
      ->capture_default_str();
  int64_t max_image_pixels;
  ws::AddMaxImagePixelsOption(app, max_image_pixels);
  if (auto rc = cli.Parse(argc, argv)) return *rc;

  try {
    const ws::StereoCornerFinder finder(ws::ParseBoardSpec(board),
                                        ws::ParseChessboardMethod(chessboard_detector), ws::BoardSearch::kFast,
                                        max_image_pixels);
    ws::Process process(cli.options());
    process.log().Info("board " + board + ", chessboard detector " + chessboard_detector + ", " +
                       std::to_string(workers) + " workers, at most " + std::to_string(max_in_flight) +
                       " frames in flight");
    ws::CornerStage stage(process, finder, workers, max_in_flight);
    process.SetProgress([&] { return stage.Progress(); });
    return process.Run();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "stereo-detect: %s\n", e.what());
    return 1;
  }
}
