// bench_fisheye_models: the per-camera table of issue #13 on one set of
// corners (a STEREO_CORNERS log): RMS, views and outliers of bspline, poly12,
// kb4 and bspline_theta, as stereo-calibrate solves them by default and
// with --outlier-sigma S --board-warp (S = 6 unless given), beside cv::fisheye::calibrate
// (Kannala-Brandt, as OpenCV's samples call it) on the same detections.
// bench/fisheye/run.sh adds mrcal's LENSMODEL_SPLINED_STEREOGRAPHIC.
//
// cv::fisheye cannot take a view with a corner near or beyond 90 degrees off
// axis (its start divides by tan theta): it gets the views whose corners all
// lie below --opencv-max-theta degrees under the bspline_theta solution, the
// best OpenCV can be given.
//   bench_fisheye_models --in-url 'file://corners.lcmlog?speed=0' [--knots 21]
#include <cmath>
#include <cstdio>
#include <optional>

#include "calib/calibrate.h"
#include "calib/evaluate/heldout.h"
#include "calib/node/corners_message.h"
#include "lcm_io/channels.h"
#include "opencv_fisheye_fit.h"
#include "runtime/process.h"
#include "runtime/process_cli.h"
#include "widestereo/stereo_corners_t.hpp"

namespace {

using namespace ws::calib;
using ws::Camera;
using ws::CameraModel;
using ws::ModelKind;
using ws::ModelName;

struct Row {
  std::string name;
  bool failed = false;
  std::string error;
  double rms[2] = {0, 0};
  int views[2] = {0, 0}, outliers[2] = {0, 0}, corners[2] = {0, 0};
  bool camera_failed[2] = {false, false};  // cv::fisheye threw on that camera's views
};

// cv::fisheye::calibrate on the views of `data` whose corners all lie below
// max_theta under `camera` (every view when camera is null).
Row OpenCvFisheye(const CameraData& data, const CameraModel* camera, double max_theta, int c, Row row) {
  const std::optional<Camera> model = camera ? std::optional<Camera>(*camera) : std::nullopt;
  const auto fit = ws::bench::FitOpenCvFisheye(data, [&](const BoardView& view) {
    if (!model) return true;
    for (const auto& u : view.image) {
      const auto ray = model->Unproject(u);
      if (!ray || !(std::atan2(ray->head<2>().norm(), ray->z()) < max_theta)) return false;
    }
    return true;
  });
  row.rms[c] = fit.rms_px;
  row.corners[c] = fit.corners;
  row.views[c] = fit.views;
  row.camera_failed[c] = fit.failed;
  if (fit.failed) std::fprintf(stderr, "cv::fisheye::calibrate, camera %d: %s\n", c, fit.error.c_str());
  return row;
}

// Every other view: even views train each camera alone, odd views test it
// (BabelCalib's protocol: the camera fixed, each test pose fitted, every
// corner; the board as the training estimated it); cv::fisheye is given no
// test here.
void PrintHeldOut(const StereoData& data, bool mono, int knots, double outlier_sigma) {
  std::printf("held out (train: even views, test: odd views; test RMS px over every corner)\n");
  const CameraData* cameras[2] = {&data.left, &data.right};
  for (const ModelKind kind : {ModelKind::kKb4, ModelKind::kBsplineTheta})
    for (int s = 0; s < 2; ++s) {
      CalibrationOptions options;
      options.model = kind;
      options.spline.knots = knots;
      if (s == 1) {
        options.outliers = OutlierRule::kSigma;
        options.outlier_sigma = outlier_sigma;
        options.board_warp = WarpRule::kEstimated;
      }
      std::printf("%-52s", (ModelName(kind) + (s ? ", outlier rejection + board warp" : "")).c_str());
      for (int c = 0; c < (mono ? 1 : 2); ++c) {
        CameraData train = *cameras[c], test = *cameras[c];
        for (size_t v = 0; v < train.views.size(); ++v) (v % 2 ? train : test).views[v] = BoardView();
        try {
          const CameraCalibration fit = CalibrateCamera(train, options);
          const HeldOutFit held = FitHeldOutViews(fit.model, test, 6, fit.board_warp);
          std::printf("   train %.4f (%2d) test %.4f (%2d)", fit.rms_px, fit.views, held.rms_px, held.views);
        } catch (const CalibrationError& e) {
          std::printf("   failed: %s", e.what());
        }
      }
      std::printf("\n");
    }
}

void Print(const std::vector<Row>& rows, bool mono) {
  std::printf("%-52s %30s", "model", "left: RMS px (views, outliers %)");
  if (!mono) std::printf(" %31s", "right");
  std::printf("\n");
  for (const Row& r : rows) {
    std::printf("%-52s", r.name.c_str());
    if (r.failed) {
      std::printf(" failed: %s\n", r.error.c_str());
      continue;
    }
    for (int c = 0; c < (mono ? 1 : 2); ++c) {
      if (r.camera_failed[c]) {
        std::printf("   %10s (%2d views, threw)      ", "failed", r.views[c]);
        continue;
      }
      const int all = r.corners[c] + r.outliers[c];
      std::printf("   %10.4f (%2d, %2d = %4.1f %%)", r.rms[c], r.views[c], r.outliers[c],
                  all ? 100.0 * r.outliers[c] / all : 0.0);
    }
    std::printf("\n");
  }
}

}  // namespace

int main(int argc, char** argv) {
  ws::ProcessCli cli("bench_fisheye_models",
                     "Per-camera RMS, views and outliers of every model and of cv::fisheye on the "
                     "corners of a STEREO_CORNERS log (issue #13's table).");
  int knots = 21;
  double opencv_max_theta_deg = 88;
  double outlier_sigma = 6;
  bool heldout = false;
  cli.app().add_option("--knots", knots, "bspline_theta's (and bspline's) estimated coefficients");
  cli.app().add_option("--opencv-max-theta", opencv_max_theta_deg,
                       "cv::fisheye gets the views whose corners lie below this angle (degrees)");
  cli.app().add_option("--outlier-sigma", outlier_sigma,
                       "The second setting's outlier rejection (with --board-warp)");
  cli.app().add_flag("--heldout", heldout,
                     "Also train on the even views and test on the odd ones (held-out RMS)");
  if (auto rc = cli.Parse(argc, argv)) return *rc;
  try {
    ws::Process process(cli.options());
    StereoData data;
    process.Subscribe<widestereo::stereo_corners_t>(
        ws::channel::kStereoCorners, [&](const auto& msg) { AddStereoCorners(data, msg); });
    if (const int rc = process.Run()) return rc;
    const bool mono = data.right.image_width == 0;
    const std::vector<ModelKind> kinds = {ModelKind::kBspline, ModelKind::kPoly12, ModelKind::kKb4,
                                          ModelKind::kBsplineTheta};
    std::vector<Row> rows;
    const CameraModel* theta_camera[2] = {nullptr, nullptr};
    ModelCalibrations settings[2];
    for (int s = 0; s < 2; ++s) {
      CalibrationOptions options;
      options.spline.knots = knots;
      if (s == 1) {
        options.outliers = OutlierRule::kSigma;
        options.outlier_sigma = outlier_sigma;
        options.board_warp = WarpRule::kEstimated;
      }
      settings[s] = CalibrateStereoAllModels(data, options, kinds);
      const std::string suffix =
          s == 0 ? "" : ", --outlier-sigma " + std::to_string(int(outlier_sigma)) + " --board-warp";
      for (const auto& f : settings[s].failed) {
        Row row;
        row.name = f.model + suffix;
        row.failed = true;
        row.error = f.error;
        rows.push_back(row);
      }
      for (const StereoCalibration& result : settings[s].solved) {
        Row row;
        row.name = ModelName(result.model) + suffix + (mono || result.flow == StereoFlow::kJoint ? "" : " (paper)");
        const CameraCalibration* cameras[2] = {&result.left, &result.right};
        for (int c = 0; c < (mono ? 1 : 2); ++c) {
          row.rms[c] = cameras[c]->rms_px;
          row.views[c] = cameras[c]->views;
          row.outliers[c] = cameras[c]->outliers;
          row.corners[c] = cameras[c]->points;
          if (s == 0 && result.model == ModelKind::kBsplineTheta) theta_camera[c] = &cameras[c]->model;
        }
        rows.push_back(row);
      }
    }
    Row opencv;
    opencv.name = "cv::fisheye::calibrate";
    const CameraData* cameras[2] = {&data.left, &data.right};
    for (int c = 0; c < (mono ? 1 : 2); ++c)
      opencv = OpenCvFisheye(*cameras[c], theta_camera[c], opencv_max_theta_deg * M_PI / 180, c, opencv);
    rows.push_back(opencv);
    Print(rows, mono);
    for (int s = 0; s < 2; ++s)  // projection uncertainty (beside mrcal_uncertainty.py's)
      for (const StereoCalibration& result : settings[s].solved)
        for (const CameraCalibration* camera : {&result.left, &result.right})
          if (camera->uncertainty.median_px >= 0)
            std::printf("%s%s %s\n", ModelName(result.model).c_str(), s ? " + warp" : "",
                        UncertaintyLine(*camera).c_str());
    if (heldout) PrintHeldOut(data, mono, knots, outlier_sigma);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_fisheye_models: %s\n", e.what());
    return 1;
  }
}
