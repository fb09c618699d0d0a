// stereo-import-corners: board corners detected by another tool (BabelCalib's
// .dsc + .orpc, mrcal's corners.vnl) as STEREO_CORNERS, so that
// stereo-calibrate calibrates them as it calibrates stereo-detect's. One
// message a view with the corners as the left camera's (a one-camera rig);
// or, with --pairs, one message a stereo frame, its left and right images
// paired by two globs as mrcal-calibrate-cameras pairs them:
//   stereo-import-corners --babelcalib ov_plane.dsc corners/train/*.orpc --out-url 'file://c.lcmlog?mode=w'
//   stereo-import-corners --mrcal corners.vnl --board chessboard:10x10:0.03 --image-size 1920x1080 ...
//   stereo-import-corners --mrcal corners.vnl --board ... --image-size ... --pairs '*left*' '*right*' ...
#include <cstdio>

#include "calib/node/corner_import.h"
#include "calib/node/corners_message.h"
#include "calib/solver/calib_data.h"
#include "board/board_spec.h"
#include "lcm_io/channels.h"
#include "runtime/process.h"
#include "runtime/process_cli.h"
#include "widestereo/stereo_corners_t.hpp"

int main(int argc, char** argv) {
  ws::ProcessCli cli("stereo-import-corners",
                     "Publishes board corners detected by another tool on STEREO_CORNERS (one "
                     "message a view, as the left camera of a one-camera rig; with --pairs one "
                     "message a stereo frame): BabelCalib's target .dsc and per-image .orpc files, "
                     "or mrcal's corners.vnl. Without --out-url they go to a log file "
                     "(LOG_DIR/stereo-import-corners.lcmlog), never to the live bus.");
  std::string dsc, vnl, board, image_size;
  std::vector<std::string> orpc, pairs;
  auto& app = cli.app();
  app.add_option("--babelcalib", dsc, "BabelCalib target description (.dsc)");
  app.add_option("orpc", orpc, "BabelCalib corner files (.orpc), one a view, in this order");
  app.add_option("--mrcal", vnl, "mrcal corners.vnl (# filename x y level)");
  app.add_option("--board", board, "With --mrcal: chessboard:COLSxROWS:SQUARE_METRES");
  app.add_option("--image-size", image_size, "With --mrcal: WIDTHxHEIGHT in pixels (both cameras)");
  app.add_option("--pairs", pairs,
                 "With --mrcal: LEFTGLOB RIGHTGLOB, shell globs matched against the vnl's file "
                 "names; a left and a right image are one stereo frame when every '*' of the two "
                 "globs matched the same text ('*left*' '*right*': /d/left-07.png with "
                 "/d/right-07.png). An image seen by one camera only stays a one-camera view; "
                 "images matching neither glob are left out")
      ->expected(2);
  if (auto rc = cli.Parse(argc, argv)) return *rc;

  try {
    if (dsc.empty() == vnl.empty()) throw std::invalid_argument("give one of --babelcalib or --mrcal");
    if (!pairs.empty() && vnl.empty()) throw std::invalid_argument("--pairs needs --mrcal");
    ws::calib::StereoData data;
    std::string board_id = board, summary;
    if (!dsc.empty()) {
      if (orpc.empty()) throw std::invalid_argument("--babelcalib needs .orpc files");
      data.left = ws::calib::ReadBabelCalibViews(dsc, orpc);
      data.right.views.resize(data.left.views.size());
      board_id = "babelcalib:" + dsc;
    } else {
      const ws::BoardSpec spec = ws::ParseBoardSpec(board);
      int width = 0, height = 0;
      char x = 0, rest = 0;
      if (std::sscanf(image_size.c_str(), "%d%c%d%c", &width, &x, &height, &rest) != 3 || x != 'x')
        throw std::invalid_argument("--image-size must be WIDTHxHEIGHT, not '" + image_size + "'");
      if (pairs.empty()) {
        data.left = ws::calib::ReadMrcalCorners(vnl, spec.cols, spec.rows, spec.square, width, height);
        data.right.views.resize(data.left.views.size());
      } else {
        const auto paired = ws::calib::PairMrcalViews(
            ws::calib::ReadMrcalViews(vnl, spec.cols, spec.rows, spec.square), pairs[0], pairs[1],
            width, height);
        data = paired.data;
        int left = 0, right = 0;
        for (size_t v = 0; v < data.left.views.size(); ++v) {
          left += !paired.left_names[v].empty();
          right += !paired.right_names[v].empty();
        }
        summary = " (" + std::to_string(left) + " left and " + std::to_string(right) +
                  " right images; " + std::to_string(paired.unmatched) + " matching neither glob left out)";
        if (left == 0 || right == 0)
          throw std::invalid_argument("--pairs '" + pairs[0] + "' '" + pairs[1] + "' matched " +
                                      std::to_string(left) + " left and " + std::to_string(right) +
                                      " right images of " + vnl);
      }
    }
    ws::ProcessOptions options = cli.options();
    options.batch = true;  // files in: without --out-url, a log file out
    ws::Process process(options);
    for (int v = 0; v < data.size(); ++v) {
      widestereo::stereo_corners_t msg{};
      msg.frame_id = v;
      msg.utime = int64_t(v) * 100000;  // 10 views a second of message time
      msg.left = ws::calib::ToCornersMessage(data.left.views[v], board_id, data.left.image_width,
                                             data.left.image_height);
      // A one-camera rig's right camera has no image (size 0).
      msg.right = ws::calib::ToCornersMessage(data.right.views[v], board_id, data.right.image_width,
                                              data.right.image_height);
      process.Publish(ws::channel::kStereoCorners, msg);
    }
    process.log().Info("published " + std::to_string(data.size()) + (pairs.empty() ? " views" : " stereo frames") +
                       summary);
    return process.Finish();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "stereo-import-corners: %s\n", e.what());
    return 1;
  }
}
