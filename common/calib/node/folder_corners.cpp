#include "calib/node/folder_corners.h"

#include <algorithm>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>

#include <opencv2/imgcodecs.hpp>

#include "detect/board_size_check.h"
#include "lcm_io/channels.h"
#include "lcm_io/decode.h"
#include "lcm_io/lcm_log.h"
#include "lcm_io/image_codec.h"
#include "runtime/atomic_file.h"
#include "runtime/ordered_pipeline.h"
#include "runtime/stop_request.h"
#include "source/dir_source.h"
#include "source/image_header.h"

namespace ws::calib {
namespace {

// Every image of the folder that may be decoded (image_header.h: a
// regular file of at most kDefaultMaxImagePixels; the reader left the
// others out, naming them), left ones first: where a board size is looked
// for.
std::vector<std::string> AllImages(const ImageFolder& folder) {
  std::vector<std::string> images;
  auto add = [&](const std::string& path) {
    std::string why;
    if (DecodableImageSize(path, kDefaultMaxImagePixels, &why)) images.push_back(path);
  };
  for (const auto& pair : folder.pairs) add(pair.left);
  for (const auto& pair : folder.pairs)
    if (!pair.right.empty()) add(pair.right);
  return images;
}

// Why no image shows `board`, and the size that some do show, if any.
std::string NoBoardAdvice(const ImageFolder& folder, const BoardSpec& board) {
  std::string advice = "no " + std::to_string(board.cols) + "x" + std::to_string(board.rows) +
                       " board in any image";
  if (board.type != BoardType::chessboard) return advice + ": check --board";
  // Sizes are tried on a few images; the one found is then counted in all.
  constexpr size_t kTried = 6;
  std::vector<cv::Mat> images;
  for (const std::string& path : AllImages(folder)) {
    images.push_back(cv::imread(path, cv::IMREAD_GRAYSCALE));
    if (images.size() == kTried) break;
  }
  for (const cv::Size& size : NeighbourSizes(board)) {
    bool shown = false;
    for (const cv::Mat& image : images) shown = shown || (!image.empty() && ShowsChessboard(image, size));
    if (!shown) continue;
    int found = 0;
    const auto all = AllImages(folder);
    for (const std::string& path : all) {
      const cv::Mat image = cv::imread(path, cv::IMREAD_GRAYSCALE);
      found += !image.empty() && ShowsChessboard(image, size);
    }
    return advice + "; " + std::to_string(size.width) + "x" + std::to_string(size.height) +
           " boards are found in " + std::to_string(found) + " of " + std::to_string(all.size()) +
           " images: --board " + WithSize(board, size) +
           " (COLSxROWS counts inner corners: a board of 10x7 squares is 9x6)";
  }
  return advice + " (sizes one corner off tried too): check --board (COLSxROWS counts inner corners, "
                  "a board of 10x7 squares is 9x6) and that the images show the whole board";
}

// One image's corners, or why it could not be searched.
struct ImageCorners {
  void Find(const StereoCornerFinder& finder, const widestereo::image_t& image) {
    try {
      corners = finder.FindInImage(image, &unrefined);
    } catch (const std::exception& e) {
      error = e.what();
    }
  }
  widestereo::camera_corners_t corners{};
  int unrefined = 0;
  std::string error;
};

// A pair's corners, its two images searched by two jobs.
struct PairCorners {
  widestereo::stereo_corners_t corners{};
  ImageCorners left, right;
};

// The names, the first kShown of them and how many more.
std::string List(const std::vector<std::string>& names) {
  constexpr size_t kShown = 20;
  std::string text;
  for (size_t i = 0; i < std::min(names.size(), kShown); ++i) text += (i ? ", " : "") + names[i];
  if (names.size() > kShown) text += " and " + std::to_string(names.size() - kShown) + " more";
  return text;
}

}  // namespace

FolderCorners DetectFolder(const std::string& dir, bool mono, const StereoCornerFinder& finder, int workers,
                           const std::string& corners_log, TextLog& log) {
  FolderCorners result;
  result.folder = FindImageFolder(dir, mono);
  const bool one_camera = result.folder.layout == FolderLayout::kOneCamera;
  DirSource source(dir, result.folder, false);
  // The corners' log is written whole at the end, every write checked
  // (atomic_file.h): a full disk is an error naming it, never a log cut
  // short that the solve would then read as damaged.
  std::vector<LcmLogEvent> events;
  // A job per image, up to 16 a core in flight: an image holding part of a
  // board (seconds of search, chessboard_detectors.cpp) keeps one core while
  // the others go on through the next ones, delivered in order. Bounded by
  // the decoded images' bytes too (kInFlightBytes, at least two a core).
  constexpr size_t kInFlightBytes = size_t(512) << 20;
  std::optional<OrderedPipeline> pipeline;
  const int64_t total = int64_t(result.folder.pairs.size());
  std::string first_board;  // the first left image with the board, and its corners
  std::vector<cv::Point2f> first_corners;
  for (int64_t id = 0; !StopRequested(); ++id) {
    std::optional<StereoPair> pair = source.Next();
    for (const std::string& event : source.TakeEvents()) log.Info(event);
    if (!pair) break;
    if (pair->left.empty()) {
      result.unreadable.push_back(pair->label);
      log.Error(pair->label + ": left out");
      continue;
    }
    ++result.read;
    result.names[id] = pair->label;
    if (!pipeline) {
      const size_t image_bytes = std::max<size_t>(1, pair->left.total() * pair->left.elemSize());
      const size_t most = std::clamp(kInFlightBytes / image_bytes, size_t(2 * workers), size_t(16 * workers));
      pipeline.emplace(OrderedPipeline::Options{workers, int(most), OrderedPipeline::WhenFull::wait});
    }
    widestereo::stereo_frame_t frame{};
    frame.frame_id = id;
    frame.utime = (id + 1) * 100000;
    frame.left = MatToImage(pair->left, frame.utime);
    frame.right = one_camera ? NoImage(frame.utime) : MatToImage(pair->right, frame.utime);
    const ImagePairPaths paths = result.folder.pairs[size_t(id)];
    // One job per image, not per pair: a pair whose one image holds part
    // of a board then keeps one core, not both. The pair's last job
    // delivers it, and finds both done (the pipeline delivers in order).
    auto shared = std::make_shared<const widestereo::stereo_frame_t>(std::move(frame));
    auto pair_corners = std::make_shared<PairCorners>();
    pair_corners->corners.utime = shared->utime;
    pair_corners->corners.frame_id = shared->frame_id;
    auto deliver = [&, pair_corners, paths] {
      PairCorners& found = *pair_corners;
      for (const auto& [image, path] : {std::pair{&found.left, paths.left}, std::pair{&found.right, paths.right}}) {
        if (image->error.empty()) continue;
        const std::string name = ImageName(path, dir);
        result.unreadable.push_back(name);
        log.Error(name + ": " + image->error + ": left out");
        return;
      }
      widestereo::stereo_corners_t& corners = found.corners;
      corners.left = found.left.corners;
      corners.right = one_camera ? finder.NoCamera() : found.right.corners;
      events.push_back({int64_t(events.size()), corners.utime, channel::kStereoCorners, EncodeMessage(corners)});
      result.unrefined += found.left.unrefined + found.right.unrefined;
      if (corners.left.n > 0) {
        ++result.left_boards;
        if (first_board.empty()) {
          first_board = paths.left;
          for (int i = 0; i < corners.left.n; ++i)
            first_corners.emplace_back(float(corners.left.image_points[i][0]), float(corners.left.image_points[i][1]));
        }
      } else {
        result.left_without_board.push_back(ImageName(paths.left, dir));
      }
      if (one_camera) return;
      if (corners.right.n > 0)
        ++result.right_boards;
      else
        result.right_without_board.push_back(ImageName(paths.right, dir));
    };
    pipeline->Submit([&, shared, pair_corners, deliver]() -> OrderedPipeline::Delivery {
      pair_corners->left.Find(finder, shared->left);
      return one_camera ? OrderedPipeline::Delivery(deliver) : [] {};
    });
    if (!one_camera)
      pipeline->Submit([&, shared, pair_corners, deliver]() -> OrderedPipeline::Delivery {
        pair_corners->right.Find(finder, shared->right);
        return deliver;
      });
    if ((id + 1) * 10 / total != id * 10 / total)  // about ten lines however many images
      log.Progress("finding the board: " + std::to_string(id + 1) + " of " + std::to_string(total) + " " +
                   (one_camera ? "images" : "pairs"));
  }
  if (pipeline) pipeline->Drain();
  if (StopRequested()) throw Stopped();  // the log of part of the folder is no log of it: none
  const std::string what = one_camera ? " images" : " pairs";
  log.Info("read " + std::to_string(result.read) + " of " + std::to_string(total) + what + " (" +
           LayoutName(result.folder.layout) + ")");
  if (result.read == 0)
    throw std::runtime_error("nothing in " + dir + " could be read as " +
                             (one_camera ? "an image" : "two images of one size and type"));
  const std::string of = " of " + std::to_string(result.read);
  log.Info("board " + finder.board().id + " found: left " + std::to_string(result.left_boards) + of +
           (one_camera ? "" : ", right " + std::to_string(result.right_boards) + of));
  if (result.unrefined > 0)
    log.Info(std::to_string(result.unrefined) +
             " corners dropped: their sub-pixel refinement failed (left at whole pixels)");
  if (!result.left_without_board.empty()) log.Info("no board in: " + List(result.left_without_board));
  if (!result.right_without_board.empty()) log.Info("no board in: " + List(result.right_without_board));
  if (result.left_boards + result.right_boards == 0)
    throw std::runtime_error(NoBoardAdvice(result.folder, finder.board()));
  if (const auto larger = first_board.empty() ? std::nullopt
                                              : LargerBoardShown(cv::imread(first_board, cv::IMREAD_GRAYSCALE),
                                                                 finder.board(), first_corners))
    throw std::runtime_error(
        ImageName(first_board, dir) + " shows a " + std::to_string(larger->width) + "x" +
        std::to_string(larger->height) + " board: a " + std::to_string(finder.board().cols) + "x" +
        std::to_string(finder.board().rows) +
        " one is only part of it, numbered from a different corner in each image. Give the whole board: "
        "--board " + WithSize(finder.board(), *larger) + " (COLSxROWS counts inner corners)");
  WriteFileAtomically(corners_log, EncodeLcmLog(events));
  return result;
}

}  // namespace ws::calib
