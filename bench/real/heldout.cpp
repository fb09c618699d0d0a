// heldout: BabelCalib's protocol on STEREO_CORNERS logs (bench/real/run.sh):
// the cameras of a calibration held fixed, each test view's board pose
// fitted alone, and the RMS over every corner of the test views, per camera.
//
//   heldout --test TEST.lcmlog --calib CALIB.yaml [--report REPORT.json]
//     stereo-calibrate's cameras (and the board's bow its report gives, as
//     the training estimated it);
//   heldout --test TEST.lcmlog --opencv-fisheye TRAIN.lcmlog
//     cv::fisheye::calibrate on each camera's train views first (its
//     fitted RMS printed too), its K, D held as the kb4 camera.
// One line a camera: "NAME held out RMS X px over V views (N corners)".
#include <cstdio>
#include <fstream>
#include <string>

#include <CLI/CLI.hpp>
#include <lcm/lcm-cpp.hpp>
#include <nlohmann/json.hpp>

#include "calib/evaluate/heldout.h"
#include "calib/node/corners_message.h"
#include "lcm_io/channels.h"
#include "opencv_fisheye_fit.h"
#include "rig/rig_file.h"
#include "widestereo/stereo_corners_t.hpp"

namespace {

using namespace ws::calib;

StereoData ReadCornersLog(const std::string& path) {
  lcm::LogFile log(path, "r");
  if (!log.good()) throw std::runtime_error("cannot read " + path);
  StereoData data;
  while (const lcm::LogEvent* event = log.readNextEvent()) {
    if (event->channel != ws::channel::kStereoCorners) continue;
    widestereo::stereo_corners_t msg;
    if (msg.decode(event->data, 0, event->datalen) != event->datalen)
      throw std::runtime_error(path + ": a STEREO_CORNERS message does not decode");
    AddStereoCorners(data, msg);
  }
  return data;
}

// The board's bow the report of camera `index` gives (flat when none).
BoardWarp WarpFromReport(const std::string& path, size_t index, const StereoData& test) {
  BoardWarp warp;
  if (path.empty()) return warp;
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  nlohmann::json report = nlohmann::json::parse(in);
  if (report.contains("models")) {  // several models solved: the file is the chosen one's
    nlohmann::json chosen;
    for (const auto& model : report["models"])
      if (model.value("model", "") == report.value("chosen", "")) chosen = model;
    report = chosen;
  }
  const auto& cameras = report.at("cameras");
  if (index >= cameras.size() || !cameras[index].contains("board_warp")) return warp;
  const auto& bow = cameras[index]["board_warp"];
  warp.data = {1e-3 * bow.at("x2_mm").get<double>(), 1e-3 * bow.at("y2_mm").get<double>()};
  warp.extent = ExtentOf({&test.left, &test.right});
  return warp;
}

void Print(const std::string& name, const HeldOutFit& held) {
  std::printf("%s held out RMS %.4f px over %d views (%d corners)\n", name.c_str(), held.rms_px, held.views,
              held.points);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("Held-out RMS (BabelCalib's protocol: cameras fixed, each test pose fitted) of a "
               "calibration, or of cv::fisheye trained on a log, on the views of a corners log.");
  std::string test_log, calib, report, train_log;
  app.add_option("--test", test_log, "STEREO_CORNERS log of the test views")->required();
  app.add_option("--calib", calib, "stereo-calibrate's calibration file");
  app.add_option("--report", report, "its report (for the board's bow)");
  app.add_option("--opencv-fisheye", train_log, "STEREO_CORNERS log to train cv::fisheye on instead");
  CLI11_PARSE(app, argc, argv);
  try {
    if (calib.empty() == train_log.empty()) throw std::invalid_argument("give one of --calib or --opencv-fisheye");
    const StereoData test = ReadCornersLog(test_log);
    const CameraData* tests[2] = {&test.left, &test.right};
    if (!calib.empty()) {
      const ws::Rig file = ws::ReadCalibrationFile(calib);
      const ws::CameraModel* models[2] = {&file.left, &file.right};
      for (int c = 0; c < (file.mono ? 1 : 2); ++c)
        Print(tests[c]->name, FitHeldOutViews(*models[c], *tests[c], 6, WarpFromReport(report, c, test)));
      return 0;
    }
    const StereoData train = ReadCornersLog(train_log);
    const CameraData* trains[2] = {&train.left, &train.right};
    for (int c = 0; c < (train.right.image_width == 0 ? 1 : 2); ++c) {
      const auto fit = ws::bench::FitOpenCvFisheye(*trains[c]);
      if (fit.failed) {
        std::printf("%s cv::fisheye failed on %d views: %s\n", trains[c]->name.c_str(), fit.views,
                    fit.error.substr(0, fit.error.find('\n')).c_str());
        continue;
      }
      std::printf("%s cv::fisheye RMS %.4f px over %d views (%d corners)\n", trains[c]->name.c_str(), fit.rms_px,
                  fit.views, fit.corners);
      Print(tests[c]->name, FitHeldOutViews(fit.kb4, *tests[c]));
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "heldout: %s\n", e.what());
    return 1;
  }
}
