// The stereo-calibrate process's behaviour, on a ws::Process:
//
//  - STEREO_CORNERS: each message becomes a stereo view unless it is a near
//    duplicate of one it has (CalibrationSession), kept in the state file.
//  - STEREO_COMMAND (target "" or "stereo-calibrate"):
//      "solve" [model=bspline|poly6|poly12|all] [knots=N]: solve the views so far
//              (a solve never changes the views)
//      "reset"  archive every view and start with none (CalibrationSession)
//      "restore" bring the views of the newest archive back
//      "save"   [path=NAME.yaml] [report=NAME.json]: write the last solution
//              again, to --out and --report or to those names in their folders
//              (plain file names only: runtime/output_folder.h)
//  - CALIBRATION_STATUS every second of the process clock (the message clock
//    when replaying a log): state (collecting, solving, solved, failed),
//    views per camera, coverage grids, RMS of the last solve (-1: none) and
//    a hint for the person holding the board.
//  - After a solve: STEREO_CALIBRATION (the first model asked for), the
//    calibration file (--out; with several models also one per model,
//    calib.poly6.yaml), the report (--report), the figures
//    (--plot-dir: distortion_curves.png, residual_map.png) and, with several
//    models, Table II on the terminal and in the log.
//  - --once: solve when a file:// input ends (or at the first solve command),
//    then exit; exit code 1 when that solve or writing its files fails.
//
// Replaying a log, solves run in the message handler, so the same log gives
// the same output; live they run on a worker thread so that the status keeps
// coming while Ceres works.
#pragma once

#include <atomic>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "calib/calibrate.h"
#include "calib/calibration_session.h"
#include "runtime/process.h"
#include "widestereo/command_t.hpp"

namespace ws::calib {

struct NodeOptions {
  std::vector<std::string> models{"bspline"};  // solved in this order; the first is published
  CalibrationOptions calibration;
  SessionOptions session;
  std::string out_yaml, report_json, plot_dir;
  std::string rig_name;  // in the figures' titles; empty: the --out file's name
  bool once = false;
};

// "all" -> every registered kind; else the one kind (checked).
std::vector<std::string> ParseModelList(const std::string& spec);

class CalibrateNode {
 public:
  CalibrateNode(Process& process, NodeOptions options);
  ~CalibrateNode();

  // Restores the state file, subscribes, starts the status timer.
  void Start();

 private:
  void OnCorners(const widestereo::stereo_corners_t& msg);
  void OnCommand(const widestereo::command_t& msg);
  void PublishStatus();
  void Solve(std::vector<std::string> models, CalibrationOptions options);
  // Solves and writes every output; false (after reporting why) when the
  // solve or writing the calibration file or report failed.
  bool SolveNow(const StereoData& data, const std::vector<std::string>& models,
                const CalibrationOptions& options);
  // The calibration file and report of `results`; throws when one cannot be written.
  void WriteFiles(const ModelCalibrations& results, const std::string& yaml,
                  const std::string& json);
  void SetState(const std::string& state, double rms, double heldout_rms = -1);

  Process& process_;
  NodeOptions options_;
  CalibrationSession session_;
  std::mutex mutex_;  // guards state_, rms_, last_
  std::string state_ = "collecting";
  double rms_ = -1;
  double heldout_rms_ = -1;
  ModelCalibrations last_;
  std::atomic<bool> solving_{false};
  std::thread worker_;
};

}  // namespace ws::calib
