#include "calib/calibrate_node.h"

#include <cstdio>
#include <filesystem>
#include <sstream>

#include "calib/calib_file.h"
#include "calib/calib_message.h"
#include "calib/calib_plots.h"
#include "calib/report.h"
#include "calib/table2.h"
#include "lcm_io/channels.h"
#include "models/model_registry.h"

namespace ws::calib {

std::vector<std::string> ParseModelList(const std::string& spec) {
  const auto kinds = ModelKinds();
  if (spec == "all") return kinds;
  if (std::find(kinds.begin(), kinds.end(), spec) == kinds.end())
    throw CalibrationError("unknown model '" + spec + "' (bspline, poly6, poly12 or all)");
  return {spec};
}

std::vector<StereoCalibration> SolveAndWrite(const StereoData& data,
                                             const std::vector<std::string>& models,
                                             const CalibrationOptions& options,
                                             const std::string& out_yaml,
                                             const std::string& report_json,
                                             const std::string& plot_dir) {
  std::vector<StereoCalibration> results = CalibrateStereoAllModels(data, options, models);
  if (!out_yaml.empty()) WriteCalibrationFile(out_yaml, ToCalibrationFile(results.front()));
  if (!report_json.empty())
    WriteJsonFile(report_json, results.size() == 1 ? StereoReport(results.front())
                                                   : ModelsReport(results));
  if (!plot_dir.empty()) {
    std::filesystem::create_directories(plot_dir);
    WriteDistortionCurvesPng(results, plot_dir + "/distortion_curves.png");
    WriteResidualMapPng(results, plot_dir + "/residual_map.png");
  }
  return results;
}

CalibrateNode::CalibrateNode(Process& process, NodeOptions options)
    : process_(process), options_(std::move(options)), session_(options_.session) {}

CalibrateNode::~CalibrateNode() {
  if (worker_.joinable()) worker_.join();
}

void CalibrateNode::Start() {
  const int restored = session_.Restore();
  if (restored > 0)
    process_.log().Info("restored " + std::to_string(restored) + " views from " +
                        options_.session.state_path);
  process_.Subscribe<widestereo::stereo_corners_t>(
      channel::kStereoCorners, [this](const auto& msg) { OnCorners(msg); });
  process_.Subscribe<widestereo::command_t>(channel::kStereoCommand,
                                            [this](const auto& msg) { OnCommand(msg); });
  process_.Every(1000000, [this] { PublishStatus(); });
  if (options_.once && process_.file_input())
    process_.AtEndOfInput([this] {
      if (!SolveNow(session_.Data(), options_.models, options_.calibration))
        throw CalibrationError("calibration failed: " + process_.options().name +
                               " could not solve the views of the log");
    });
  process_.SetProgress([this] {
    std::lock_guard<std::mutex> lock(mutex_);
    std::ostringstream line;
    line << "views " << session_.views() << " (duplicates " << duplicates_ << ") " << state_;
    if (rms_ >= 0) line << " rms " << rms_ << " px";
    return line.str();
  });
  process_.SetState("collecting");
}

void CalibrateNode::OnCorners(const widestereo::stereo_corners_t& msg) {
  std::string why;
  switch (session_.Add(msg, &why)) {
    case CalibrationSession::Outcome::kAccepted:
      ++accepted_;
      if (!why.empty()) process_.ReportError(why);
      process_.log().Detail("view " + std::to_string(session_.views()) + " accepted (frame " +
                            std::to_string(msg.frame_id) + ")");
      break;
    case CalibrationSession::Outcome::kDuplicate: ++duplicates_; break;
    case CalibrationSession::Outcome::kNoBoard: break;
    case CalibrationSession::Outcome::kRejected:
      ++rejected_;
      process_.ReportError("frame " + std::to_string(msg.frame_id) + " not used: " + why);
      break;
  }
}

void CalibrateNode::OnCommand(const widestereo::command_t& msg) {
  if (!msg.target.empty() && msg.target != process_.options().name) return;
  std::vector<std::string> models = options_.models;
  CalibrationOptions calibration = options_.calibration;
  std::string path = options_.out_yaml, report;
  for (const auto& arg : msg.args) {
    const auto eq = arg.find('=');
    const std::string key = arg.substr(0, eq), value = eq == std::string::npos ? "" : arg.substr(eq + 1);
    try {
      if (key == "model") models = ParseModelList(value);
      else if (key == "knots") calibration.knots = std::stoi(value);
      else if (key == "path") path = value;
      else if (key == "report") report = value;
      else process_.ReportError("command '" + msg.command + "': unknown argument '" + arg + "'");
    } catch (const std::exception& e) {
      process_.ReportError("command '" + msg.command + "': bad argument '" + arg + "': " + e.what());
      return;
    }
  }
  if (msg.command == "solve") {
    Solve(models, calibration, options_.once);
  } else if (msg.command == "reset") {
    if (solving_) {
      process_.ReportError("reset ignored: a solve is running");
      return;
    }
    session_.Reset();
    SetState("collecting", -1);
    process_.log().Info("reset: every view forgotten");
  } else if (msg.command == "save") {
    std::vector<StereoCalibration> last;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      last = last_;
    }
    if (last.empty()) {
      process_.ReportError("save: nothing solved yet");
      return;
    }
    try {
      if (!path.empty()) WriteCalibrationFile(path, ToCalibrationFile(last.front()));
      if (!report.empty())
        WriteJsonFile(report, last.size() == 1 ? StereoReport(last.front()) : ModelsReport(last));
      process_.log().Info("saved " + path + (report.empty() ? "" : " and " + report));
    } catch (const std::exception& e) {
      process_.ReportError(std::string("save: ") + e.what());
    }
  } else {
    process_.ReportError("unknown command '" + msg.command + "' (solve, reset, save)");
  }
}

void CalibrateNode::PublishStatus() {
  std::string state;
  double rms;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    state = state_;
    rms = rms_;
  }
  process_.Publish(channel::kCalibrationStatus, session_.Status(process_.Now(), state, rms));
}

void CalibrateNode::SetState(const std::string& state, double rms) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    state_ = state;
    rms_ = rms;
  }
  process_.SetState(state);
}

void CalibrateNode::Solve(std::vector<std::string> models, CalibrationOptions options,
                          bool exit_after) {
  if (process_.file_input()) {
    SolveNow(session_.Data(), models, options);
    if (exit_after) process_.Stop();
    return;
  }
  if (solving_.exchange(true)) {
    process_.ReportError("solve ignored: a solve is already running");
    return;
  }
  if (worker_.joinable()) worker_.join();
  StereoData data = session_.Data();
  worker_ = std::thread([this, data = std::move(data), models, options, exit_after] {
    SolveNow(data, models, options);
    if (exit_after) process_.Stop();
  });
}

bool CalibrateNode::SolveNow(const StereoData& data, const std::vector<std::string>& models,
                             const CalibrationOptions& options) {
  solving_ = true;
  double previous_rms;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    previous_rms = rms_;
  }
  SetState("solving", previous_rms);
  PublishStatus();
  std::string models_text;
  for (const auto& m : models) models_text += (models_text.empty() ? "" : ", ") + m;
  process_.log().Info("solving " + std::to_string(data.size()) + " views (" + models_text + ")");
  bool ok = false;
  try {
    auto results = SolveAndWrite(data, models, options, options_.out_yaml, options_.report_json,
                                 options_.plot_dir);
    const StereoCalibration& primary = results.front();
    process_.Publish(channel::kStereoCalibration, ToMessage(primary, process_.Now()));
    for (const auto& r : results) {
      std::ostringstream line;
      line << r.model << ": left rms " << r.left.rms_px << " px (" << r.left.views
           << " views, " << r.left.outliers << " outliers), right rms " << r.right.rms_px
           << " px (" << r.right.views << " views, " << r.right.outliers
           << " outliers), stereo rms " << r.rms_px << " px (" << r.views << " views), baseline "
           << r.T.norm() << " m";
      process_.log().Info(line.str());
      for (const auto* cam : {&r.left, &r.right})
        for (const auto& skipped : cam->skipped) process_.log().Detail(cam->name + " " + skipped);
    }
    if (results.size() > 1) {
      std::istringstream table(FormatTableII(TableRows(results)));
      for (std::string line; std::getline(table, line);) process_.log().Info(line);
    }
    if (!options_.out_yaml.empty()) process_.log().Info("wrote " + options_.out_yaml);
    if (!options_.report_json.empty()) process_.log().Info("wrote " + options_.report_json);
    {
      std::lock_guard<std::mutex> lock(mutex_);
      last_ = results;
    }
    SetState("solved", primary.rms_px);
    ok = true;
  } catch (const std::exception& e) {
    process_.ReportError(std::string("solve failed: ") + e.what());
    SetState("failed", -1);
  }
  PublishStatus();
  solving_ = false;
  return ok;
}

}  // namespace ws::calib
