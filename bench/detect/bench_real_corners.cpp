// bench_real_corners: stereo-detect's chessboard detection against OpenCV's
// own on real images, boards found and how well one model fits the corners.
//
//   bench_real_corners --board chessboard:8x6:0.04 --images 'DIR/left-*.png' [--images 'DIR/right-*.png']
//       [--model kb4|poly6]
//     per glob (one camera): the boards found by OpenCV's findChessboardCorners
//     with its default flags (adaptive threshold + normalise), alone and as
//     stereo-detect's opencv detector (then cornerSubPix in its window), its
//     findChessboardCornersSB (no flags, and exhaustive + normalise), and
//     stereo-detect's classic (searching for every board, as stereo-calibrate
//     --images does) and sb detectors, with the seconds each took,
//     and every image whose board OpenCV's default call finds and classic
//     does not; then the model (kb4, cv::fisheye's, by default; poly6,
//     cv::calibrateCamera's, for a pinhole lens) fitted, no outlier
//     rejection, no board warp, to the views found by both OpenCV's default
//     call and classic: on OpenCV's corners refined as its calibration
//     tutorial does (cornerSubPix, winSize 11 x 11: a 23 x 23 window), as
//     stereo-detect's opencv detector does, moved from there to their saddle
//     points at the fixed scale of 1/20 of the grid spacing stereo-detect used
//     before, and at the scales corner_refinement.h chooses now, and on
//     classic's corners.
//   bench_real_corners --babelcalib T.dsc A.orpc B.orpc ...
//     corners another tool found (each .orpc beside its image, NAME.png),
//     refined from there by cv::cornerSubPix (as OpenCV's detector does) and
//     by cornerSubPix + the saddle points (as stereo-detect does), and kb4
//     fitted to each, and to the given corners themselves.
// Lower fitted RMS on the same views means corners closer to a smooth lens.
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "bench_support.h"
#include "calib/calibrate.h"
#include "calib/node/corner_import.h"
#include "calib/node/corners_message.h"
#include "detect/corner_refinement.h"
#include "detect/grid_order.h"
#include "detect/saddle_point.h"
#include "detect/stereo_corner_finder.h"
#include "lcm_io/image_codec.h"

namespace {

using ws::calib::BoardView;
using ws::calib::CameraData;
using ws::calib::ToBoardView;

double Seconds(const std::function<void()>& run) { return 1e-3 * ws::bench::Milliseconds(run); }

void PrintFit(const std::string& name, const CameraData& data, ws::ModelKind model = ws::ModelKind::kKb4) {
  ws::calib::CalibrationOptions options;
  options.model = model;
  options.outliers = ws::calib::OutlierRule::kOff;
  options.board_warp = ws::calib::WarpRule::kFlat;
  options.nonradial = ws::calib::FieldRule::kNone;
  options.covariance = false;
  options.cv_folds = 0;
  try {
    const auto fit = ws::calib::CalibrateCamera(data, options);
    std::printf("  %s on %-48s RMS %.4f px (%d views, %d corners)\n", ws::ModelName(model).c_str(), name.c_str(),
                fit.rms_px, fit.views, fit.points);
  } catch (const std::exception& e) {
    std::printf("  %s on %-48s failed: %s\n", ws::ModelName(model).c_str(), name.c_str(), e.what());
  }
}

// `view` with its corners at `points`.
BoardView WithPoints(BoardView view, const std::vector<cv::Point2f>& points) {
  for (size_t i = 0; i < points.size(); ++i) view.image[i] = {points[i].x, points[i].y};
  return view;
}

// The saddle points at one scale for the whole board, 1/20 of its shortest
// spacing (at least 1 px): stereo-detect's refinement before the scale was
// chosen per corner.
std::vector<cv::Point2f> FixedScaleSaddles(const cv::Mat& gray, const std::vector<double>& spacing,
                                           std::vector<cv::Point2f> points) {
  const ws::SaddleWindow window(std::max(1.0, 0.05 * *std::min_element(spacing.begin(), spacing.end())));
  for (cv::Point2f& p : points)
    if (const auto fit = window.Fit(gray, p)) p = fit->point;
  return points;
}

// OpenCV's detection as its calibration tutorial calls it: findChessboardCorners
// with its default flags, then cornerSubPix with winSize 11 x 11 and (EPS +
// COUNT, 30, 0.001); in stereo-detect's grid order. Empty where it finds no board.
BoardView OpenCvTutorialView(const ws::BoardSpec& board, const cv::Mat& gray, bool* found) {
  std::vector<cv::Point2f> points;
  *found = cv::findChessboardCorners(gray, board.pattern_size(), points);
  if (!*found) return {};
  cv::cornerSubPix(gray, points, cv::Size(11, 11), cv::Size(-1, -1),
                   cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 30, 0.001));
  if (!ws::OrderChessboardCorners(gray, board.pattern_size(), points)) return {};
  BoardView view;
  for (int id = 0; id < int(points.size()); ++id) {
    const cv::Point3d object = board.ObjectPoint(id);
    view.ids.push_back(id);
    view.object.emplace_back(object.x, object.y, object.z);
    view.image.emplace_back(points[id].x, points[id].y);
  }
  return view;
}

void Images(const ws::BoardSpec& board, const std::string& pattern, ws::ModelKind model) {
  std::vector<cv::String> files;
  cv::glob(pattern, files);
  if (files.empty()) throw std::runtime_error("no image matches " + pattern);
  // classic as stereo-calibrate --images runs it on a folder, every search.
  const ws::StereoCornerFinder opencv(board, ws::ChessboardMethod::opencv),
      classic(board, ws::ChessboardMethod::classic, ws::BoardSearch::kEveryBoard),
      sb(board, ws::ChessboardMethod::sb);
  int found[6] = {}, both = 0, unrefined = 0;
  double seconds[6] = {};
  std::vector<std::string> missed;
  CameraData ours, theirs, tutorial, fixed, chosen;
  for (const cv::String& file : files) {
    const cv::Mat gray = cv::imread(file, cv::IMREAD_GRAYSCALE);
    if (gray.empty()) throw std::runtime_error("cannot read " + file);
    for (CameraData* data : {&ours, &theirs, &tutorial, &fixed, &chosen}) {
      data->image_width = gray.cols;
      data->image_height = gray.rows;
    }
    const widestereo::image_t image = ws::MatToImage(gray, 0);
    BoardView views[4];
    bool plain = false;
    std::vector<cv::Point2f> sb_points;
    seconds[0] += Seconds([&] { views[3] = OpenCvTutorialView(board, gray, &plain); });
    seconds[1] += Seconds([&] { views[0] = ToBoardView(opencv.FindInImage(image)); });
    seconds[2] += Seconds([&] { found[2] += cv::findChessboardCornersSB(gray, board.pattern_size(), sb_points); });
    seconds[3] += Seconds([&] {
      found[3] += cv::findChessboardCornersSB(gray, board.pattern_size(), sb_points,
                                              cv::CALIB_CB_EXHAUSTIVE | cv::CALIB_CB_NORMALIZE_IMAGE);
    });
    int dropped = 0;
    seconds[4] += Seconds([&] { views[1] = ToBoardView(classic.FindInImage(image, &dropped)); });
    seconds[5] += Seconds([&] { views[2] = ToBoardView(sb.FindInImage(image)); });
    unrefined += dropped;
    found[0] += plain;
    found[1] += !views[0].empty();
    found[4] += !views[1].empty();
    found[5] += !views[2].empty();
    if (plain && views[1].empty()) missed.push_back(file);
    if (views[3].empty() || views[0].empty() || views[1].empty()) continue;
    ++both;
    tutorial.views.push_back(views[3]);
    theirs.views.push_back(views[0]);
    ours.views.push_back(views[1]);
    const std::vector<double> spacing = ws::calib::NeighbourSpacing(views[0]);
    std::vector<cv::Point2f> start;
    for (const auto& p : views[0].image) start.emplace_back(float(p.x()), float(p.y()));
    std::vector<cv::Point2f> moved = FixedScaleSaddles(gray, spacing, start);
    fixed.views.push_back(WithPoints(views[0], moved));
    moved = start;
    ws::RefineCorners(gray, moved, spacing, start);
    chosen.views.push_back(WithPoints(views[0], moved));
  }
  std::printf("%s: %zu images, boards found (seconds):\n", pattern.c_str(), files.size());
  const char* names[6] = {"OpenCV findChessboardCorners, default flags (adaptive + normalise)",
                          "  the same + cornerSubPix (stereo-detect's opencv detector)",
                          "OpenCV findChessboardCornersSB",
                          "OpenCV findChessboardCornersSB (exhaustive + normalise)",
                          "stereo-detect classic (every board)",
                          "stereo-detect sb"};
  for (int i = 0; i < 6; ++i) std::printf("  %-70s %3d (%.2f s)\n", names[i], found[i], seconds[i]);
  std::printf("  boards OpenCV's default call finds and classic does not: %zu\n", missed.size());
  for (const std::string& file : missed) std::printf("    %s\n", file.c_str());
  std::printf("  corners classic dropped, their refinement failed: %d\n", unrefined);
  std::printf("  views found by OpenCV's default call and classic: %d\n", both);
  PrintFit("OpenCV's corners (cornerSubPix 11 x 11, its tutorial's)", tutorial, model);
  PrintFit("OpenCV's corners (cornerSubPix, stereo-detect's window)", theirs, model);
  PrintFit("the same + saddles at 1/20 of the spacing", fixed, model);
  PrintFit("the same + saddles at chosen scales", chosen, model);
  PrintFit("stereo-detect classic's corners", ours, model);
}

void BabelCalib(const std::string& dsc, const std::vector<std::string>& orpc) {
  const CameraData given = ws::calib::ReadBabelCalibViews(dsc, orpc);
  CameraData subpix = given, from_subpix = given, saddle = given;
  int fell_back = 0, corners = 0;
  for (size_t v = 0; v < orpc.size(); ++v) {
    const std::string image = orpc[v].substr(0, orpc[v].rfind('.')) + ".png";
    const cv::Mat gray = cv::imread(image, cv::IMREAD_GRAYSCALE);
    if (gray.empty()) throw std::runtime_error("cannot read " + image);
    const std::vector<double> spacing = ws::calib::NeighbourSpacing(given.views[v]);
    std::vector<cv::Point2f> start;
    for (const auto& p : given.views[v].image) start.emplace_back(float(p.x()), float(p.y()));
    std::vector<cv::Point2f> refined = start, fallback = start;
    ws::CornerSubPix(gray, fallback, spacing);
    subpix.views[v] = WithPoints(given.views[v], fallback);
    fell_back += ws::RefineCorners(gray, refined, spacing, fallback);
    saddle.views[v] = WithPoints(given.views[v], refined);
    refined = fallback;
    ws::RefineCorners(gray, refined, spacing, fallback);
    from_subpix.views[v] = WithPoints(given.views[v], refined);
    corners += int(start.size());
  }
  std::printf("%s: %zu views\n", dsc.c_str(), orpc.size());
  PrintFit("the given corners", given);
  PrintFit("cornerSubPix from there", subpix);
  PrintFit("saddle points from cornerSubPix's", from_subpix);
  PrintFit("saddle points from the given (else cornerSubPix)", saddle);
  std::printf("  (the saddle points fell back to cornerSubPix at %d of %d corners)\n", fell_back, corners);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("Boards found and corner accuracy (one model's fitted RMS) of stereo-detect's chessboard "
               "detection against OpenCV's own, on real images.");
  std::string board = "chessboard:9x6:0.025", dsc, model = "kb4";
  std::vector<std::string> images, orpc;
  app.add_option("--board", board, "The chessboard (stereo-detect's --board)")->capture_default_str();
  app.add_option("--images", images, "A glob of one camera's images (quote it); repeat per camera");
  app.add_option("--model", model, "The model fitted to the --images views: kb4 (fisheye) or poly6 (pinhole)")
      ->check(CLI::IsMember({"kb4", "poly6"}))
      ->capture_default_str();
  app.add_option("--babelcalib", dsc, "BabelCalib target (.dsc); the .orpc files follow");
  app.add_option("orpc", orpc, "BabelCalib corner files, each beside its image");
  CLI11_PARSE(app, argc, argv);
  try {
    for (const std::string& pattern : images) Images(ws::ParseBoardSpec(board), pattern, ws::ParseModelKind(model));
    if (!dsc.empty()) BabelCalib(dsc, orpc);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_real_corners: %s\n", e.what());
    return 1;
  }
}
