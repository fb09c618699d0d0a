// stereo-calibrate: collects board corners from STEREO_CORNERS, tells the
// person holding the board where corners are still missing, solves the
// stereo calibration on a 'solve' command (or, with --once, at the end of a
// replayed log) and writes and publishes it. With --images it is the whole
// chain in one process: a folder of images to a calibration file, no bus.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <thread>

#include "calib/node/calibrate_node.h"
#include "calib/node/folder_corners.h"
#include "calib/node/run_outputs.h"
#include "lcm_io/lcm_log.h"
#include "models/model_registry.h"
#include "runtime/atomic_file.h"
#include "runtime/output_folder.h"
#include "runtime/process_cli.h"
#include "runtime/stop_request.h"

namespace {

// calib.yaml -> calib.SUFFIX, beside it.
std::string Beside(const std::string& file, const std::string& suffix) {
  std::filesystem::path path(file);
  return path.replace_extension(suffix).string();
}

// The corners' log of a run not yet done, beside where it goes.
constexpr const char* kPending = ".partial";

}  // namespace

int main(int argc, char** argv) {
  ws::ProcessCli cli("stereo-calibrate",
                     "Calibrates a stereo rig from the board corners on STEREO_CORNERS (Zhang's "
                     "start, then a joint Ceres solve of every camera parameter, the B-spline or "
                     "polynomial distortion, R, T and every board pose). Publishes "
                     "CALIBRATION_STATUS (coverage and a hint) and CALIBRATION_VIEWS (every view held, its "
                     "RMS in the last solve) every second and, after a solve "
                     "(a 'solve' command on STEREO_COMMAND, or --once at the end of a replayed "
                     "log), STEREO_CALIBRATION; writes the calibration file and report.\n\n"
                     "A folder of images to a calibration, with no bus:\n"
                     "  stereo-calibrate --images DIR --board chessboard:9x6:0.025 --out calib.yaml\n\n"
                     "Batch runs (--images, or a file:// --in-url) never publish on the live bus: without "
                     "--out-url their output goes to a log file beside the report. A calibration whose file "
                     "cannot be written is not published.");
  ws::calib::NodeOptions node;
  ws::calib::CalibrationOptions& calib = node.calibration;
  std::string model = "all", flow = "joint", loss = "none", state, knots = "auto";
  std::string outliers = "auto", warp = "auto", nonradial = "auto";
  std::string images, board, corners_log;
  bool mono = false;
  auto& app = cli.app();
  app.add_option("--images", images,
                 "A folder of calibration images: left*/right* names, left/ + right/ or cam0/ + cam1/ "
                 "folders, or one camera's images. Finds the board (--board) in every image and solves "
                 "at once, in this process (no bus). Beside --out go NAME.report.json, NAME.plots/, "
                 "NAME.corners.lcmlog (the corners: --in-url solves them again) and NAME.lcmlog (the "
                 "messages, not published)");
  app.add_option("--board", board,
                 "With --images: chessboard:COLSxROWS:SQUARE or charuco:COLSxROWS:SQUARE:MARKER:DICT "
                 "(inner corners, metres), as stereo-detect's");
  app.add_flag("--mono", mono, "With --images: every image of the folder alone, a one-camera rig");
  std::vector<std::string> models = ws::ModelNames();
  models.push_back("all");
  app.add_option("--model", model,
                 "bspline, poly6, poly12 (pinhole radius), kb4, bspline_theta (incidence angle, "
                 "fisheye lenses beyond 180 degrees) or all: every model solved (Table II), the "
                 "simplest, unless a richer one predicts held-out views better beyond the folds' "
                 "spread, written to --out and published (the one rule of every choice, "
                 "docs/calibration.md); a model that cannot follow the lens is reported")
      ->check(CLI::IsMember(models))
      ->capture_default_str();
  app.add_option("--knots", knots,
                 "Estimated B-spline coefficients (distinct knots), 2 to 64, or auto: per camera "
                 "more only where they predict held-out views better beyond the folds' spread")
      ->capture_default_str();
  app.add_option("--cv-folds", calib.cv_folds,
                 "Folds of the cross-validation (held-out RMS, --knots auto; fewer with fewer than two views a fold); 0: none")
      ->check(CLI::Range(0, 100))
      ->capture_default_str();
  app.add_option("--smoothness", calib.spline.smoothness,
                 "B-spline smoothness prior weight lambda (0: off)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--flow", flow,
                 "joint (one solve of everything) or paper (cameras first, then R, T)")
      ->check(CLI::IsMember({"joint", "paper"}))
      ->capture_default_str();
  app.add_option("--robust-loss", loss, "none, huber or cauchy (scale --robust-scale)")
      ->check(CLI::IsMember({"none", "huber", "cauchy"}))
      ->capture_default_str();
  app.add_option("--robust-scale", calib.robust_scale_px, "Robust loss scale, pixels")
      ->capture_default_str();
  app.add_option("--outlier-sigma", outliers,
                 "Corners left out as outliers: auto (farther from their projection than "
                 "sigma sqrt(2 ln 2N), Chauvenet's criterion for N corners, sigma the inliers' "
                 "RMS per coordinate or the corners' own noise if larger), K (farther than K "
                 "times the median-based noise, at least 0.25 px) or off")
      ->capture_default_str();
  app.add_option("--board-warp", warp,
                 "The board's bow (mrcal's calobject_warp paraboloid; reported in mm): auto "
                 "(estimated, kept where it lowers the held-out RMS beyond the folds' spread), "
                 "on or off")
      ->check(CLI::IsMember({"auto", "on", "off"}))
      ->capture_default_str();
  app.add_option("--nonradial", nonradial,
                 "The lens model's non-radial part, a sensor tilt (OpenCV's tauX, tauY) and a "
                 "smooth 2-D field over the image: auto (the tilt kept where it lowers the "
                 "held-out RMS beyond the folds' spread; where the held-out RMS exceeds the "
                 "corners' own noise by more than it resolves, fields of 16 control points "
                 "across at smoothness weights from 10 down to 0.01 and grids of 4 to 11 across "
                 "tried; a richer one kept only where it predicts better beyond the spread), none, "
                 "tilt, COLSxROWS "
                 "or tilt+COLSxROWS (at --smoothness)")
      ->capture_default_str();
  app.add_option("--min-views", calib.min_views, "Views each camera needs")
      ->check(CLI::Range(3, 1000))
      ->capture_default_str();
  app.add_option(
         "--duplicate-px", node.session.duplicate_px,
         "A view whose corners are on average this close to a kept view's is a near duplicate "
         "(0: 4 times the noise of its corners, measured from the board's rows and columns: a "
         "board held still)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--max-views", node.session.max_views,
                 "Views the session keeps at most; more are rejected, counted and logged")
      ->check(CLI::Range(3, 100000))
      ->capture_default_str();
  app.add_flag("--once", node.once,
               "Solve at the end of a file:// input (or at the first solve command) and exit");
  app.add_option("--out", node.out_yaml,
                 "Calibration file to write (YAML, cv::FileStorage) of the model published; with several "
                 "models also FILE.MODEL.yaml for each (calib.poly6.yaml); a 'save path=NAME' command writes "
                 "only NAME in its folder");
  app.add_option("--report", node.report_json,
                 "Report to write (JSON); a 'save report=NAME' command writes only NAME in its folder");
  app.add_option("--plot-dir", node.plot_dir,
                 "Folder for distortion_curves.png, residual_map.png, projection_uncertainty.png "
                 "and, with --knots auto, knot_curve.png (needs gnuplot)");
  app.add_option("--rig-name", node.rig_name,
                 "The rig's name in the figures' titles (default: the --out file's name)");
  app.add_option("--preview-every", node.preview_s,
                 "Live, while collecting (before the first solve), every this many seconds when the views "
                 "changed: a quick solve of the views so far (the first model, fixed knots, each camera alone, "
                 "no cross-validation) whose projection uncertainty goes on CALIBRATION_PREVIEW for the live "
                 "page; nothing is written. 0: never")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--state", state,
                 "File keeping the accepted views across restarts ('reset' archives it beside itself as "
                 "NAME-<UTC time>.lcmlog, 'restore' brings the newest back, 'remove frame=ID' takes one view out and "
                 "keeps it in NAME-removed.lcmlog; a damaged one is kept as "
                 "NAME-damaged-<UTC time>.lcmlog and its intact views recovered); 'none' for none. Default: "
                 "LOG_DIR/stereo-calibrate-views.lcmlog live, none when replaying a log");
  if (auto rc = cli.Parse(argc, argv)) return *rc;

  try {
    node.models = ws::calib::ParseModelList(model);
    calib.model = node.models.front();
    calib.spline.knots = ws::calib::ParseKnots(knots);
    calib.outliers = ws::calib::ParseOutlierRule(outliers, &calib.outlier_sigma);
    ws::calib::ParseFieldRule(nonradial, &calib);
    calib.board_warp = warp == "on"    ? ws::calib::WarpRule::kEstimated
                       : warp == "off" ? ws::calib::WarpRule::kFlat
                                       : ws::calib::WarpRule::kAuto;
    calib.flow = flow == "paper" ? ws::calib::StereoFlow::kPaper : ws::calib::StereoFlow::kJoint;
    calib.robust_loss = loss == "huber"    ? ws::calib::RobustLoss::kHuber
                        : loss == "cauchy" ? ws::calib::RobustLoss::kCauchy
                                           : ws::calib::RobustLoss::kNone;
    node.session.min_views = calib.min_views;
    ws::ProcessOptions options = cli.options();
    if (!images.empty()) {
      if (!options.in_url.empty())
        throw std::invalid_argument("--images reads the folder itself: give --images or --in-url, not both");
      if (board.empty())
        throw std::invalid_argument("--images needs --board, e.g. chessboard:9x6:0.025 (9x6 inner corners, "
                                    "25 mm squares)");
      if (node.out_yaml.empty()) throw std::invalid_argument("--images needs --out CALIB.yaml");
      if (node.report_json.empty()) node.report_json = Beside(node.out_yaml, ".report.json");
      if (node.plot_dir.empty()) node.plot_dir = Beside(node.out_yaml, ".plots");
      // The corners are solved from a name of their own, put in place when
      // the run succeeds: until then an older NAME.corners.lcmlog stands.
      corners_log = std::filesystem::absolute(Beside(node.out_yaml, ".corners.lcmlog")).string();
      options.in_url = "file://" + corners_log + kPending + "?speed=0";
      node.once = true;
      if (app.get_option("--log-dir")->count() == 0)  // the text log beside the calibration too
        options.log_dir = std::filesystem::path(node.out_yaml).parent_path().string();
      if (options.log_dir.empty()) options.log_dir = ".";
    } else if (!board.empty() || mono) {
      throw std::invalid_argument("--board and --mono go with --images (live, stereo-detect finds the board)");
    }
    const bool replay = options.in_url.rfind("file://", 0) == 0;
    if (state.empty() && !replay) state = options.log_dir + "/stereo-calibrate-views.lcmlog";
    node.session.state_path = state == "none" ? "" : state;
    if (!node.out_yaml.empty() || !node.report_json.empty())
      options.batch_out = Beside(node.out_yaml.empty() ? node.report_json : node.out_yaml, ".lcmlog");
    ws::calib::CheckOptions(calib);
    ws::RequireWritableFolderOf("--out", node.out_yaml);
    ws::RequireWritableFolderOf("--report", node.report_json);
    ws::calib::RunOutputs outputs{node.out_yaml, {}, node.report_json, node.plot_dir,
                                  corners_log, options.batch_out};
    if (!node.out_yaml.empty() && node.models.size() > 1)
      for (ws::ModelKind kind : node.models) outputs.model_yamls.push_back(ws::calib::ModelFilePath(node.out_yaml, kind));
    ws::calib::RequireSafeOutputs(outputs, images);
    const std::optional<ws::StereoCornerFinder> finder =
        images.empty() ? std::nullopt
                       : std::optional<ws::StereoCornerFinder>(std::in_place, ws::ParseBoardSpec(board),
                                                               ws::kDefaultChessboardMethod,
                                                               ws::BoardSearch::kEveryBoard);

    // A run that fails or is stopped leaves no log of its own behind, and
    // the old ones whole (the calibration and report are put in place only
    // when all are written: atomic_file.h; the messages' log by the process;
    // the corners' log here).
    options.batch_out_when_done = true;
    const std::string corners_pending = corners_log.empty() ? "" : corners_log + kPending;
    auto remove_pending_corners = [&] {
      if (!corners_pending.empty()) std::filesystem::remove(corners_pending);
    };
    auto run = [&]() -> int {
      ws::Process process(options);
      if (finder) {
        ws::calib::FolderCorners found;
        try {
          found = ws::calib::DetectFolder(images, mono, *finder, std::max(1, int(std::thread::hardware_concurrency())),
                                          corners_pending, process.log());
        } catch (const ws::Stopped&) {
          process.DiscardBatchOutput();
          return process.Finish();  // SIGTERM or Ctrl-C: nothing solved, nothing written
        }
        node.frame_names = found.names;
        process.log().Info("corners in " + corners_log +
                           " (to solve them again with other options: --in-url 'file://" + corners_log +
                           "?speed=0' --once)");
      }
      ws::calib::CalibrateNode calibrate(process, node);
      calibrate.Start();
      return process.Run();
    };
    int rc = 1;
    try {
      rc = run();
    } catch (...) {
      remove_pending_corners();
      throw;
    }
    // Stopped (status 0 too) or failed: nothing of this run's stands.
    if (rc != 0 || ws::StopRequested()) {
      remove_pending_corners();
    } else if (!corners_pending.empty()) {
      std::filesystem::rename(corners_pending, corners_log);  // throws naming both files
    }
    return rc;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "stereo-calibrate: %s\n", e.what());
    return 1;
  }
}
