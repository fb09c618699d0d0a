// The stereo-calibrate process's behaviour, on a ws::Process:
//
//  - STEREO_CORNERS: each message becomes a stereo view unless it is a near
//    duplicate of one it has (CalibrationSession), kept in the state file.
//  - STEREO_COMMAND (target "" or "stereo-calibrate"):
//      "solve" [model=bspline|poly6|poly12|all] [knots=N]: solve the views so far
//              (a solve never changes the views)
//      "reset"  archive every view and start with none (CalibrationSession)
//      "restore" bring the views of the newest archive back
//      "remove" frame=ID [utime=US]: take the view of that STEREO_CORNERS
//              frame out (CalibrationSession::Remove); an unknown view is refused
//      "save"   [path=NAME.yaml] [report=NAME.json]: write the last solution
//              again, to --out and --report or to those names in their folders
//              (plain file names only: runtime/output_folder.h)
//  - CALIBRATION_STATUS every second of the process clock (the message clock
//    when replaying a log): state (collecting, solving, solved, failed),
//    views per camera, coverage grids, RMS of the last solve (-1: none) and
//    a hint for the person holding the board; with it CALIBRATION_VIEWS,
//    every view held and its RMS in the last solve.
//  - Live, while collecting (before the first solve, after a reset or a
//    removal), every preview_s when the views changed: a quick solve of the
//    views so far on a thread of its own (preview_solve.h), its projection
//    uncertainty on CALIBRATION_PREVIEW; nothing written, STEREO_CALIBRATION
//    and CALIBRATION_RESULT untouched.
//  - After a solve: the calibration file (--out; with several models also
//    one per model, calib.poly6.yaml), the report (--report), the figures
//    (--plot-dir: distortion_curves.png, residual_map.png), Table II and
//    every warning that changes the result (views left out, outliers,
//    models that failed; named by their images when frame_names has them)
//    on the terminal and in the log; then, once the calibration file is
//    written, STEREO_CALIBRATION (the model chosen, calibrate.h's Chosen)
//    and CALIBRATION_RESULT (the model table and the chosen model's maps,
//    result_message.h).
//    A calibration whose file cannot be written is not published.
//  - --once: solve when a file:// input ends (or at the first solve command),
//    then exit; exit code 1 when there is no view, or that solve or writing
//    its files fails.
//
// Replaying a log, solves run in the message handler, so the same log gives
// the same output; live they run on a worker thread so that the status keeps
// coming while Ceres works.
#pragma once

#include <atomic>
#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "calib/calibrate.h"
#include "calib/node/calibration_session.h"
#include "runtime/command_dispatcher.h"
#include "runtime/process.h"
#include "widestereo/command_t.hpp"

namespace ws::calib {

struct NodeOptions {
  std::vector<ModelKind> models{ModelKind::kBspline};  // solved in this order
  CalibrationOptions calibration;
  SessionOptions session;
  std::string out_yaml, report_json, plot_dir;
  std::string rig_name;  // in the figures' titles; empty: the --out file's name
  bool once = false;
  double preview_s = 10;  // seconds between previews at least; 0: none
  // The images each STEREO_CORNERS frame id came from (--images), to name
  // views in messages; without a name a view is "view 3 (frame 7)".
  std::map<int64_t, std::string> frame_names;
};

// "all" -> every registered kind; else the one kind (checked).
std::vector<ModelKind> ParseModelList(const std::string& spec);

// Where a model's own file goes beside the calibration file of several
// models: calib.yaml and poly6 -> calib.poly6.yaml (always .yaml).
std::string ModelFilePath(const std::string& yaml, ModelKind model);

class CalibrateNode {
 public:
  CalibrateNode(Process& process, NodeOptions options);
  ~CalibrateNode();

  // Restores the state file, subscribes, starts the status timer.
  void Start();

 private:
  void OnCorners(const widestereo::stereo_corners_t& msg);
  CommandDispatcher Commands();
  void OnCommand(const CommandArgs& args);
  void Remove(const CommandArgs& args);
  void PublishStatus();
  // Starts a preview solve when one is due (NodeOptions::preview_s).
  void MaybePreview();
  // Reports what the session's last read of its state file found damaged.
  void ReportStateDamage();
  void Solve(std::vector<ModelKind> models, CalibrationOptions options);
  // Solves the views (`frames`: the frame id of each), writes every output
  // and publishes; false (after reporting why) when the solve or writing the
  // calibration file or report failed.
  bool SolveNow(const StereoData& data, const std::vector<int64_t>& frames, const std::vector<int64_t>& utimes,
                const std::vector<ModelKind>& models, const CalibrationOptions& options);
  // Keeps each solved view's RMS per camera, by its frame id and utime.
  void KeepViewRms(const StereoCalibration& solved, const std::vector<int64_t>& frames,
                   const std::vector<int64_t>& utimes);
  // "view 3 (left04.jpg + right04.jpg)", or "view 3 (frame 7)" without names.
  std::string ViewName(int view, const std::vector<int64_t>& frames) const;
  // `text` with every "view N" named as ViewName does: one numbering in
  // every message.
  std::string NameViews(const std::string& text, const std::vector<int64_t>& frames) const;
  // Every choice the published calibration rests on (the model, then each
  // camera's), its candidates and why the winner won (selection.h).
  void ReportChoices(const ModelCalibrations& results);
  // The warnings of the published calibration that change the result: views
  // left out (of a camera, of R, T), outliers, renumbered boards, the joint
  // solve left out.
  void ReportLeftOut(const StereoCalibration& result, const std::vector<int64_t>& frames);
  // The calibration file and report of `results`; throws when one cannot be written.
  void WriteFiles(const ModelCalibrations& results, const std::string& yaml,
                  const std::string& json);
  void SetState(const std::string& state, double rms, double heldout_rms = -1);

  Process& process_;
  NodeOptions options_;
  CalibrationSession session_;
  CommandDispatcher commands_;
  std::mutex mutex_;  // guards state_, rms_, last_, view_rms_, solve_utime_
  std::string state_ = "collecting";
  double rms_ = -1;
  double heldout_rms_ = -1;
  ModelCalibrations last_;
  std::map<std::pair<int64_t, int64_t>, std::pair<double, double>> view_rms_;  // (frame, utime) -> left, right
  int64_t solve_utime_ = 0;
  std::atomic<bool> solving_{false};
  std::vector<int64_t> solving_frames_;  // the running solve's views' frames (NameViews)
  std::thread worker_;
  std::atomic<bool> previewing_{false};
  int64_t last_preview_us_ = 0;
  std::vector<int64_t> previewed_utimes_;  // the views of the last preview
  std::thread preview_worker_;
};

}  // namespace ws::calib
