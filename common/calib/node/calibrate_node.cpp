#include "calib/node/calibrate_node.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <map>
#include <optional>
#include <regex>
#include <sstream>
#include <tuple>

#include "calib/node/calib_plots.h"
#include "calib/node/preview_solve.h"
#include "calib/node/report.h"
#include "calib/node/result_message.h"
#include "calib/node/solved_rig.h"
#include "calib/node/table2.h"
#include "lcm_io/channels.h"
#include "models/model_registry.h"
#include "rig/publish_calibration.h"
#include "rig/rig_file.h"
#include "runtime/atomic_file.h"
#include "runtime/escaped.h"
#include "runtime/json_file.h"
#include "runtime/output_folder.h"
#include "runtime/stop_request.h"
#include "runtime/wall_clock.h"

namespace ws::calib {

std::string ModelFilePath(const std::string& yaml, ModelKind model) {
  const std::filesystem::path path(yaml);
  return (path.parent_path() / (path.stem().string() + "." + ModelName(model) + ".yaml")).string();
}

namespace {

// The folder of an output file (--out, --report), where `save` may write; ""
// when the option was not given.
std::string FolderOf(const std::string& file) {
  if (file.empty()) return "";
  const std::filesystem::path parent = std::filesystem::path(file).parent_path();
  return parent.empty() ? "." : parent.string();
}

}  // namespace

std::vector<ModelKind> ParseModelList(const std::string& spec) {
  if (spec == "all") return ModelKinds();
  try {
    return {ParseModelKind(spec)};
  } catch (const std::invalid_argument&) {
    throw CalibrationError("unknown model '" + spec + "' (" + KnownModelNames() + " or all)");
  }
}

CalibrateNode::CalibrateNode(Process& process, NodeOptions options)
    : process_(process), options_(std::move(options)), session_(options_.session), commands_(Commands()) {
  // Every stage of a solve in the log file; on the terminal as the progress
  // line, at most one a second (the solver passes one line at a time).
  options_.calibration.progress = [this, shown = std::chrono::steady_clock::time_point()](
                                      const std::string& solver_line) mutable {
    const std::string line = NameViews(solver_line, solving_frames_);
    process_.log().Detail(line);
    const auto now = std::chrono::steady_clock::now();
    if (now - shown < std::chrono::seconds(1)) return;
    shown = now;
    process_.log().Progress("solving: " + line);
  };
}

CalibrateNode::~CalibrateNode() {
  if (worker_.joinable()) worker_.join();
  if (preview_worker_.joinable()) preview_worker_.join();
}

void CalibrateNode::Start() {
  const int restored = session_.Restore();
  if (!options_.session.state_path.empty())
    process_.log().Info("views kept in " + options_.session.state_path + " (" +
                        std::to_string(restored) + " restored)");
  ReportStateDamage();
  // stereo-detect looks for corners in the newest frame only: the frames it
  // passed over are skipped by design, not lost.
  process_.Subscribe<widestereo::stereo_corners_t>(
      channel::kStereoCorners, [this](const auto& msg) { OnCorners(msg); }, 0, Process::FrameGaps::skipped);
  process_.Subscribe<widestereo::command_t>(channel::kStereoCommand,
                                            [this](const auto& msg) { commands_.Dispatch(msg); });
  process_.Every(1000000, [this] {
    PublishStatus();
    MaybePreview();  // on this thread only
  });
  if (options_.once && process_.file_input())
    process_.AtEndOfInput([this] {
      if (session_.views() == 0)
        return process_.Fatal("no board in any frame of " + process_.options().in_url +
                              ": nothing to calibrate. Does stereo-detect's --board match the board? "
                              "(COLSxROWS counts inner corners: a board of 10x7 squares is 9x6)");
      std::vector<int64_t> frames, utimes;
      const StereoData data = session_.Data(&frames, &utimes);
      if (!SolveNow(data, frames, utimes, options_.models, options_.calibration) && !StopRequested())
        process_.Fatal("no calibration from the views of the log");
    });
  process_.SetProgress([this] {
    std::lock_guard<std::mutex> lock(mutex_);
    std::ostringstream line;
    line << "views " << session_.views() << " (near duplicates " << session_.duplicates() << ") "
         << state_;
    if (rms_ >= 0) line << ", rms " << rms_ << " px";
    if (heldout_rms_ >= 0) line << ", held-out " << heldout_rms_ << " px";
    return line.str();
  });
  process_.SetState("collecting");
}

// In the text log and the status's last error: an operator sees the damage
// and where the damaged file is.
void CalibrateNode::ReportStateDamage() {
  if (const std::string damage = session_.StateDamage(); !damage.empty()) process_.ReportError(damage);
}

void CalibrateNode::OnCorners(const widestereo::stereo_corners_t& msg) {
  std::string why;
  switch (session_.Add(msg, &why)) {
    case CalibrationSession::Outcome::kAccepted:
      if (!why.empty()) process_.ReportRecurring(why);
      process_.log().Detail("view " + std::to_string(session_.views()) + " from frame " +
                            std::to_string(msg.frame_id));
      break;
    case CalibrationSession::Outcome::kRejected:  // counted, logged at most once a period with the count
      process_.HandleRejected(channel::kStereoCorners, "frame " + std::to_string(msg.frame_id) + " not used: " + why);
      break;
    case CalibrationSession::Outcome::kDuplicate:
    case CalibrationSession::Outcome::kNoBoard:
      break;
  }
}

// Every command takes the same arguments (model, knots: the solve's;
// path, report, overwrite: the save's).
CommandDispatcher CalibrateNode::Commands() {
  const std::vector<std::string> keys = {"model", "knots", "path", "report", "overwrite"};
  const auto run = [this](const CommandArgs& args) { OnCommand(args); };
  std::vector<CommandSpec> commands;
  for (const char* name : {"solve", "reset", "restore", "save"}) commands.push_back({name, name, keys, run});
  commands.push_back({"remove", "remove frame=ID [utime=US]", {"frame", "utime"},
                      [this](const CommandArgs& args) { Remove(args); }});
  return CommandDispatcher(process_.options().name, commands);
}

// A user's removal of one view (the page's remove button, stereo-command).
void CalibrateNode::Remove(const CommandArgs& args) {
  std::optional<int64_t> frame, utime;
  for (const CommandArgs::Arg& arg : args.args) {
    size_t used = 0;
    int64_t value = 0;
    try {
      value = std::stoll(arg.value, &used);
    } catch (const std::exception&) {
    }
    if (used == 0 || used != arg.value.size()) args.Refuse(arg, "not an integer");
    (arg.key == "frame" ? frame : utime) = value;
  }
  if (!frame) throw std::invalid_argument("remove: which view? (remove frame=ID [utime=US])");
  if (solving_) throw std::runtime_error("remove refused: a solve is running");
  const std::string kept = session_.Remove(*frame, utime);  // throws for an unknown view
  process_.log().Info("remove: the view of frame " + std::to_string(*frame) + " removed" +
                      (kept.empty() ? "" : ", kept in " + kept) + "; " + std::to_string(session_.views()) +
                      " views left");
  SetState("collecting", -1);
  PublishStatus();
}

// A command it cannot carry out as sent throws (counted as rejected on
// STEREO_COMMAND).
void CalibrateNode::OnCommand(const CommandArgs& args) {
  const std::string& command = args.command;
  std::vector<ModelKind> models = options_.models;
  CalibrationOptions calibration = options_.calibration;
  CommandOutput yaml{FolderOf(options_.out_yaml), "", ".yaml"}, json{FolderOf(options_.report_json), "", ".json"};
  for (const CommandArgs::Arg& arg : args.args) {
    try {
      if (arg.key == "model")
        models = ParseModelList(arg.value);
      else if (arg.key == "knots")
        calibration.spline.knots = ParseKnots(arg.value);
      else if (arg.key == "path")
        yaml.name = arg.value;
      else if (arg.key == "report")
        json.name = arg.value;
      else if (arg.key == "overwrite" && (arg.value == "0" || arg.value == "1"))
        yaml.overwrite = json.overwrite = arg.value == "1";
      else
        throw std::invalid_argument("unknown argument");
    } catch (const std::exception& e) {
      args.Refuse(arg, e.what());
    }
  }
  // The names a save writes: the process's own --out and --report, or new
  // files of their kinds in their folders.
  auto named = [&](const CommandOutput& output, const std::string& own) {
    try {
      return output.name.empty() ? own : CommandOutputFile(output);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("command '" + command + "': " + Quoted(output.name) + ": " + e.what());
    }
  };
  const std::string yaml_path = named(yaml, options_.out_yaml), json_path = named(json, options_.report_json);
  if (command == "solve") {
    Solve(models, calibration);
  } else if (command == "reset" || command == "restore") {
    if (solving_) throw std::runtime_error(command + " refused: a solve is running");
    const int views = session_.views();
    if (command == "reset") {
      const std::string archive = session_.Reset(WallMicros());
      process_.log().Info(archive.empty() ? "reset: no view to archive"
                                          : "reset: " + std::to_string(views) + " views archived in " + archive +
                                                " ('restore' brings them back)");
    } else {
      const std::string archive = session_.RestoreLastArchive(WallMicros());
      ReportStateDamage();
      process_.log().Info("restore: " + std::to_string(session_.views()) + " views back from " + archive +
                          (views ? ", the " + std::to_string(views) + " before it archived" : ""));
    }
    SetState("collecting", -1);
  } else {  // save
    ModelCalibrations last;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      last = last_;
    }
    if (last.solved.empty()) throw std::runtime_error("save: nothing solved yet");
    try {
      for (const std::string& path : {yaml.name.empty() ? "" : yaml_path, json.name.empty() ? "" : json_path})
        if (const std::string backup = KeepBackup(path); !backup.empty())
          process_.log().Info("save: the previous " + path + " kept as " + backup);
      WriteFiles(last, yaml_path, json_path);
    } catch (const std::exception& e) {
      throw std::runtime_error(std::string("save: ") + e.what());
    }
  }
}

void CalibrateNode::PublishStatus() {
  std::string state;
  double rms, heldout;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    state = state_;
    rms = rms_;
    heldout = heldout_rms_;
  }
  auto status = session_.Status(process_.Now(), state, rms);
  status.heldout_rms = heldout;
  process_.Publish(channel::kCalibrationStatus, status);
  auto views = session_.Views(process_.Now());
  {
    std::lock_guard<std::mutex> lock(mutex_);
    views.solve_utime = solve_utime_;
    for (auto& view : views.views)
      if (const auto found = view_rms_.find({view.frame_id, view.frame_utime}); found != view_rms_.end())
        std::tie(view.left_rms, view.right_rms) = found->second;
  }
  process_.Publish(channel::kCalibrationViews, views);
}

void CalibrateNode::MaybePreview() {
  if (options_.preview_s <= 0 || process_.file_input() || previewing_ || solving_) return;
  const auto collecting = [this] {
    std::lock_guard<std::mutex> lock(mutex_);
    return state_ == "collecting";
  };
  const int64_t now = process_.Now();
  if (!collecting() || (last_preview_us_ != 0 && now - last_preview_us_ < int64_t(options_.preview_s * 1e6))) return;
  std::vector<int64_t> utimes;
  StereoData data = session_.Data(nullptr, &utimes);
  if (data.size() < options_.calibration.min_views || utimes == previewed_utimes_) return;
  previewed_utimes_ = std::move(utimes);
  last_preview_us_ = now;
  previewing_ = true;
  if (preview_worker_.joinable()) preview_worker_.join();
  preview_worker_ = std::thread([this, collecting, data = std::move(data)] {
    try {
      const auto preview = PreviewSolve(data, options_.calibration, PreviewModel(options_.models), process_.Now());
      if (collecting() && !solving_) process_.Publish(channel::kCalibrationPreview, preview);
      process_.log().Detail("preview of " + std::to_string(data.size()) + " views published");
    } catch (const Stopped&) {
    } catch (const std::exception& e) {
      process_.log().Detail(std::string("preview: ") + e.what());
    }
    previewing_ = false;
  });
}

void CalibrateNode::KeepViewRms(const StereoCalibration& solved, const std::vector<int64_t>& frames,
                                const std::vector<int64_t>& utimes) {
  auto rms = [](const CameraCalibration& camera, size_t view) {
    return view < camera.view_rms.size() ? camera.view_rms[view] : -1.0;
  };
  std::lock_guard<std::mutex> lock(mutex_);
  view_rms_.clear();
  for (size_t v = 0; v < frames.size() && v < utimes.size(); ++v)
    view_rms_[{frames[v], utimes[v]}] = {rms(solved.left, v), rms(solved.right, v)};
  solve_utime_ = process_.Now();
}

void CalibrateNode::SetState(const std::string& state, double rms, double heldout_rms) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    state_ = state;
    rms_ = rms;
    heldout_rms_ = heldout_rms;
  }
  process_.SetState(state);
}

void CalibrateNode::Solve(std::vector<ModelKind> models, CalibrationOptions options) {
  if (solving_.exchange(true)) return process_.ReportError("solve ignored: a solve is running");
  std::vector<int64_t> frames, utimes;
  StereoData data = session_.Data(&frames, &utimes);
  if (process_.file_input()) {
    SolveNow(data, frames, utimes, models, options);
    if (options_.once) process_.Stop();
    return;
  }
  if (worker_.joinable()) worker_.join();
  worker_ = std::thread([this, data = std::move(data), frames = std::move(frames), utimes = std::move(utimes),
                         models, options] {
    const bool ok = SolveNow(data, frames, utimes, models, options);
    if (options_.once) ok || StopRequested() ? process_.Stop() : process_.Fatal("the solve failed");
  });
}

void CalibrateNode::WriteFiles(const ModelCalibrations& results, const std::string& yaml,
                               const std::string& json) {
  // One set: the calibration, each model's file and the report are put in
  // place together, or none of them (atomic_file.h).
  const bool several = results.solved.size() + results.failed.size() > 1;
  std::vector<std::string> written;
  OutputSet set;
  if (!yaml.empty()) {
    WriteCalibrationFile(yaml, ToRig(Chosen(results)));
    written.push_back(yaml);
    if (several)
      for (const StereoCalibration& result : results.solved) {
        written.push_back(ModelFilePath(yaml, result.model));
        WriteCalibrationFile(written.back(), ToRig(result));
      }
  }
  if (!json.empty()) {
    WriteJsonFile(json, several ? ModelsReport(results) : StereoReport(Chosen(results)));
    written.push_back(json);
  }
  set.Commit();
  for (const std::string& path : written) process_.log().Info("wrote " + path);
}

std::string CalibrateNode::ViewName(int view, const std::vector<int64_t>& frames) const {
  const int64_t frame = view >= 0 && view < int(frames.size()) ? frames[size_t(view)] : -1;
  const auto name = options_.frame_names.find(frame);
  return "view " + std::to_string(view) + " (" +
         (name != options_.frame_names.end() ? name->second : "frame " + std::to_string(frame)) + ")";
}

void CalibrateNode::ReportChoices(const ModelCalibrations& results) {
  const StereoCalibration& primary = Chosen(results);
  if (results.solved.size() + results.failed.size() > 1)
    for (const std::string& line : SelectionLines(results.model_selection)) process_.log().Info(line);
  for (const CameraCalibration* camera : {&primary.left, &primary.right}) {
    if (camera == &primary.right && primary.mono) break;
    for (const Selection& selection : camera->selections)
      for (const std::string& line : SelectionLines(selection))
        process_.log().Info(ModelName(primary.model) + " " + line);
  }
}

std::string CalibrateNode::NameViews(const std::string& text, const std::vector<int64_t>& frames) const {
  static const std::regex kView("view ([0-9]+)");
  std::string out;
  auto at = text.cbegin();
  for (std::sregex_iterator it(text.begin(), text.end(), kView), end; it != end; ++it) {
    out.append(at, (*it)[0].first);
    out += ViewName(std::stoi((*it)[1].str()), frames);
    at = (*it)[0].second;
  }
  return out.append(at, text.cend());
}

void CalibrateNode::ReportLeftOut(const StereoCalibration& result, const std::vector<int64_t>& frames) {
  auto named = [&](const std::string& text) { return NameViews(text, frames); };
  for (const CameraCalibration* camera : {&result.left, &result.right}) {
    if (camera == &result.right && result.mono) break;
    for (const auto& skipped : camera->skipped) process_.ReportError("warning: " + camera->name + " camera: " + named(skipped));
    if (camera->outliers == 0) continue;
    std::map<int, int> per_view;
    for (const auto& corner : camera->residuals) per_view[corner.view] += corner.outlier;
    std::string where;
    for (const auto& [view, count] : per_view)
      if (count > 0) where += (where.empty() ? "" : ", ") + ViewName(view, frames) + " " + std::to_string(count);
    process_.ReportError("warning: " + camera->name + " camera: " + std::to_string(camera->outliers) +
                         " corners left out as outliers: " + where);
  }
  for (int view : result.inconsistent_views)
    process_.ReportError("warning: " + ViewName(view, frames) +
                         ": the pair does not fit one rig (the board moved between the two exposures, or "
                         "the images are not a pair): left out of R, T");
  if (result.joint_left_out) {
    std::string pairs;
    for (int view : result.inconsistent_views) pairs += (pairs.empty() ? "" : ", ") + ViewName(view, frames);
    process_.ReportError("warning: the joint solve was left out: sharing the board poses worsens the cameras' "
                         "fit beyond chance (pairs not exposed together: " + pairs +
                         "); each camera is solved from its own views");
  }
  for (int view : result.half_turned_views)
    process_.log().Info(ViewName(view, frames) +
                        ": the right image numbered the symmetric board from the other end: renumbered");
}

bool CalibrateNode::SolveNow(const StereoData& data, const std::vector<int64_t>& frames,
                             const std::vector<int64_t>& utimes, const std::vector<ModelKind>& models,
                             const CalibrationOptions& options) {
  solving_ = true;
  solving_frames_ = frames;
  SetState("solving", -1);
  PublishStatus();
  std::string names;
  for (const ModelKind m : models) names += (names.empty() ? "" : ", ") + ModelName(m);
  process_.log().Info("solving " + std::to_string(data.size()) + " views (" + names + ")");
  bool ok = false;
  double rms = -1, heldout = -1;
  try {
    const ModelCalibrations results = CalibrateStereoAllModels(data, options, models);
    const StereoCalibration& primary = Chosen(results);
    for (const auto& failure : results.failed)
      if (failure.not_tried)
        process_.log().Info(failure.model + " " + failure.error);
      else
        process_.ReportError(failure.model + " failed: " + NameViews(failure.error, frames));
    for (const auto& r : results.solved) {
      std::ostringstream line;
      line << r.model << ": left rms " << r.left.rms_px << " px (" << r.left.views << " views, "
           << r.left.outliers << " outliers, held-out rms " << r.left.heldout_rms_px << " px)";
      if (!r.mono)
        line << ", right rms " << r.right.rms_px << " px (" << r.right.views << " views, "
             << r.right.outliers << " outliers, held-out rms " << r.right.heldout_rms_px
             << " px), stereo rms " << r.rms_px << " px (" << r.views
             << " views), baseline " << r.T.norm() << " m";
      process_.log().Info(line.str());
      for (const auto* camera : {&r.left, &r.right}) {
        if (const std::string line = OutlierLine(*camera); !line.empty())
          process_.log().Info(ModelName(r.model) + " " + line);
        if (camera->uncertainty.median_px >= 0)
          process_.log().Info(ModelName(r.model) + " " + UncertaintyLine(*camera));
      }
      for (const auto* camera : {&r.left, &r.right})
        for (const auto& skipped : camera->skipped)
          process_.log().Detail(camera->name + " " + skipped);
    }
    std::istringstream table(FormatTableII(TableRows(results.solved, results.chosen)));
    for (std::string line; std::getline(table, line);) process_.log().Info(line);
    ReportChoices(results);
    ReportLeftOut(primary, frames);
    {
      std::lock_guard<std::mutex> lock(mutex_);
      last_ = results;
    }
    WriteFiles(results, options_.out_yaml, options_.report_json);  // throws: nothing is published
    if (primary.mono)  // STEREO_CALIBRATION is a rig's message
      process_.log().Info("one-camera rig: nothing to publish on " +
                          std::string(channel::kStereoCalibration));
    else
      PublishCalibration(process_, ToMessage(primary, process_.Now()));
    process_.Publish(channel::kCalibrationResult, ToResultMessage(results, process_.Now()));
    if (!options_.plot_dir.empty()) {
      try {  // a figure that cannot be drawn (no gnuplot) costs no calibration
        std::filesystem::create_directories(options_.plot_dir);
        const std::string rig = !options_.rig_name.empty() ? options_.rig_name
                                : !options_.out_yaml.empty()
                                    ? std::filesystem::path(options_.out_yaml).stem().string()
                                    : std::string("rig");
        const std::string dir = options_.plot_dir + "/";
        WriteDistortionCurvesPng(results.solved, rig, dir + "distortion_curves.png");
        WriteResidualMapPng(results.solved, rig, dir + "residual_map.png");
        WriteKnotCurvePng(results.solved, rig, dir + "knot_curve.png");
        WriteUncertaintyPng(results.solved, rig, dir + "projection_uncertainty.png");
        process_.log().Info("wrote the figures in " + options_.plot_dir);
      } catch (const std::exception& e) {
        process_.ReportError(std::string("figures: ") + e.what());
      }
    }
    KeepViewRms(primary, frames, utimes);
    rms = primary.rms_px;
    heldout = HeldOutRms(primary);
    ok = true;
  } catch (const Stopped&) {
    process_.log().Info("solve stopped on request: nothing written or published");
  } catch (const std::exception& e) {
    process_.ReportError("solve failed: " + NameViews(e.what(), frames));
  }
  // Done before the status says so: a reset sent on seeing "solved" is obeyed.
  solving_ = false;
  SetState(ok ? "solved" : StopRequested() ? "stopped" : "failed", rms, heldout);
  PublishStatus();
  return ok;
}

}  // namespace ws::calib
