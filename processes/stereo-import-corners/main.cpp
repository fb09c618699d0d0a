// stereo-import-corners: board corners detected by another tool (BabelCalib's
// .dsc + .orpc, mrcal's corners.vnl) as STEREO_CORNERS, one message a view
// with the corners as the left camera's (a one-camera rig), so that
// stereo-calibrate calibrates them as it calibrates stereo-detect's:
//   stereo-import-corners --babelcalib ov_plane.dsc corners/train/*.orpc --out-url 'file://c.lcmlog?mode=w'
//   stereo-import-corners --mrcal corners.vnl --board chessboard:10x10:0.03 --image-size 1920x1080 ...
#include <cstdio>

#include "calib/calib_data.h"
#include "calib/corner_import.h"
#include "detect/board_spec.h"
#include "lcm_io/channels.h"
#include "runtime/process.h"
#include "runtime/process_cli.h"
#include "widestereo/stereo_corners_t.hpp"

int main(int argc, char** argv) {
  ws::ProcessCli cli("stereo-import-corners",
                     "Publishes board corners detected by another tool on STEREO_CORNERS (one "
                     "message a view, as the left camera of a one-camera rig): BabelCalib's target "
                     ".dsc and per-image .orpc files, or mrcal's corners.vnl. Without --out-url they go "
                     "to a log file (LOG_DIR/stereo-import-corners.lcmlog), never to the live bus.");
  std::string dsc, vnl, board, image_size;
  std::vector<std::string> orpc;
  auto& app = cli.app();
  app.add_option("--babelcalib", dsc, "BabelCalib target description (.dsc)");
  app.add_option("orpc", orpc, "BabelCalib corner files (.orpc), one a view, in this order");
  app.add_option("--mrcal", vnl, "mrcal corners.vnl (# filename x y level)");
  app.add_option("--board", board, "With --mrcal: chessboard:COLSxROWS:SQUARE_METRES");
  app.add_option("--image-size", image_size, "With --mrcal: WIDTHxHEIGHT in pixels");
  if (auto rc = cli.Parse(argc, argv)) return *rc;

  try {
    if (dsc.empty() == vnl.empty()) throw std::invalid_argument("give one of --babelcalib or --mrcal");
    ws::calib::CameraData data;
    std::string board_id = board;
    if (!dsc.empty()) {
      if (orpc.empty()) throw std::invalid_argument("--babelcalib needs .orpc files");
      data = ws::calib::ReadBabelCalibViews(dsc, orpc);
      board_id = "babelcalib:" + dsc;
    } else {
      const ws::BoardSpec spec = ws::ParseBoardSpec(board);
      int width = 0, height = 0;
      char x = 0, rest = 0;
      if (std::sscanf(image_size.c_str(), "%d%c%d%c", &width, &x, &height, &rest) != 3 || x != 'x')
        throw std::invalid_argument("--image-size must be WIDTHxHEIGHT, not '" + image_size + "'");
      data = ws::calib::ReadMrcalCorners(vnl, spec.cols, spec.rows, spec.square, width, height);
    }
    ws::ProcessOptions options = cli.options();
    options.batch = true;  // files in: without --out-url, a log file out
    ws::Process process(options);
    for (size_t v = 0; v < data.views.size(); ++v) {
      widestereo::stereo_corners_t msg;
      msg.frame_id = static_cast<int64_t>(v);
      msg.utime = static_cast<int64_t>(v) * 100000;  // 10 views a second of message time
      msg.left = ws::calib::ToCornersMessage(data.views[v], board_id, data.image_width,
                                             data.image_height);
      msg.right = ws::calib::ToCornersMessage({}, board_id, 0, 0);
      process.Publish(ws::channel::kStereoCorners, msg);
    }
    process.log().Info("published " + std::to_string(data.views.size()) + " views");
    return process.Finish();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "stereo-import-corners: %s\n", e.what());
    return 1;
  }
}
