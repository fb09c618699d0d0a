// Detection time per 1280x960 stereo pair: OpenCV's detector called directly
// on the images, against stereo-detect's path (decode, detect, order the
// corners, fill the message) on one worker and on two, through the ordered
// pipeline. Boards are rendered (detect/synthetic_view.h), in several poses.
//
//   build-detect/bench/bench_detect [--pairs N] [--detector classic|sb]
#include <chrono>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>
#include <opencv2/calib3d.hpp>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgproc.hpp>

#include "detect/stereo_corner_finder.h"
#include "detect/synthetic_view.h"
#include "lcm_io/image_codec.h"
#include "runtime/ordered_pipeline.h"

namespace {

using Clock = std::chrono::steady_clock;

double SecondsPerPair(int pairs, const std::function<void()>& run) {
  const auto start = Clock::now();
  run();
  return std::chrono::duration<double>(Clock::now() - start).count() / pairs;
}

std::vector<widestereo::stereo_frame_t> RenderPairs(const ws::BoardSpec& board, int count) {
  const cv::Size size(1280, 960);
  std::vector<widestereo::stereo_frame_t> frames;
  for (int i = 0; i < count; ++i) {
    ws::BoardPose pose;
    pose.roll_deg = -30 + 17 * i % 60;
    pose.tilt_x_deg = (i % 5 - 2) * 12;
    pose.tilt_y_deg = (i % 3 - 1) * 20;
    pose.fill = 0.4 + 0.05 * (i % 5);
    ws::RenderSettings settings;
    settings.size = size;
    settings.seed = uint64_t(i + 1);
    widestereo::stereo_frame_t frame{};
    frame.utime = i;
    frame.frame_id = i;
    frame.left = ws::MatToImage(ws::RenderBoard(board, ws::BoardToImage(board, pose, size), settings).image, i);
    pose.shift.x = -0.08;  // the right camera sees it further left
    frame.right = ws::MatToImage(ws::RenderBoard(board, ws::BoardToImage(board, pose, size), settings).image, i);
    frames.push_back(frame);
  }
  return frames;
}

// OpenCV's detector called directly on decoded images. `flags` for the
// classic detector: stereo-detect's (CALIB_CB_NORMALIZE_IMAGE), or the
// defaults of OpenCV's documentation (adaptive threshold, normalise, fast
// check), which are much slower on large images.
bool DetectDirectly(const cv::Mat& gray, cv::Size pattern, ws::ChessboardMethod method, int flags) {
  std::vector<cv::Point2f> corners;
  if (method == ws::ChessboardMethod::sb)
    return cv::findChessboardCornersSB(gray, pattern, corners, cv::CALIB_CB_NORMALIZE_IMAGE);
  if (!cv::findChessboardCorners(gray, pattern, corners, flags)) return false;
  cv::cornerSubPix(gray, corners, cv::Size(11, 11), cv::Size(-1, -1),
                   cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 30, 0.01));
  return true;
}

double ThroughPipeline(const ws::StereoCornerFinder& finder,
                       const std::vector<widestereo::stereo_frame_t>& frames, int workers) {
  return SecondsPerPair(int(frames.size()), [&] {
    ws::OrderedPipeline pipeline({workers, workers + 2, ws::OrderedPipeline::WhenFull::wait});
    for (const auto& frame : frames)
      pipeline.Submit([&finder, &frame] {
        auto corners = std::make_shared<widestereo::stereo_corners_t>(finder.Find(frame));
        return ws::OrderedPipeline::Delivery([corners] {
          if (corners->left.n == 0 || corners->right.n == 0) std::fprintf(stderr, "board not found\n");
        });
      });
    pipeline.Drain();
  });
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("Detection time per 1280x960 stereo pair: OpenCV directly vs stereo-detect's path");
  int pairs = 16;
  std::string detector = "classic";
  app.add_option("--pairs", pairs, "Rendered pairs to time")->check(CLI::Range(1, 1000));
  app.add_option("--detector", detector, "classic or sb")->check(CLI::IsMember({"classic", "sb"}));
  CLI11_PARSE(app, argc, argv);

  const ws::BoardSpec board = ws::ParseBoardSpec("chessboard:9x6:0.025");
  const ws::ChessboardMethod method = ws::ParseChessboardMethod(detector);
  const ws::StereoCornerFinder finder(board, method);
  const auto frames = RenderPairs(board, pairs);
  std::vector<std::pair<cv::Mat, cv::Mat>> decoded;
  for (const auto& frame : frames) decoded.emplace_back(ws::ImageToMat(frame.left), ws::ImageToMat(frame.right));

  std::printf("%d pairs of 1280x960, %s detector, OpenCV threads %d, %u cores\n", pairs, detector.c_str(),
              cv::getNumThreads(), std::thread::hardware_concurrency());
  const auto direct_with = [&](int flags) {
    return SecondsPerPair(pairs, [&] {
      for (const auto& [left, right] : decoded)
        if (!DetectDirectly(left, board.pattern_size(), method, flags) ||
            !DetectDirectly(right, board.pattern_size(), method, flags))
          std::fprintf(stderr, "board not found\n");
    });
  };
  const double direct = direct_with(cv::CALIB_CB_NORMALIZE_IMAGE);
  const double documented =
      direct_with(cv::CALIB_CB_ADAPTIVE_THRESH | cv::CALIB_CB_NORMALIZE_IMAGE | cv::CALIB_CB_FAST_CHECK);
  const double one = ThroughPipeline(finder, frames, 1);
  const double two = ThroughPipeline(finder, frames, 2);
  std::printf("OpenCV directly, same flags, one caller:   %7.1f ms per pair\n", direct * 1e3);
  if (method == ws::ChessboardMethod::classic)
    std::printf("OpenCV directly, documented default flags: %7.1f ms per pair  (%.2fx)\n", documented * 1e3,
                documented / direct);
  std::printf("stereo-detect path, 1 worker:              %7.1f ms per pair  (%.2fx OpenCV directly)\n", one * 1e3,
              one / direct);
  std::printf("stereo-detect path, 2 workers:             %7.1f ms per pair  (%.2fx OpenCV directly, %.2fx faster than 1 worker)\n",
              two * 1e3, two / direct, one / two);
  return 0;
}
