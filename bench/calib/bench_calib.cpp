// Solve time of one camera's calibration against cv::calibrateCamera on
// identical detections: synthetic board corners (9 x 6, 0.1 px noise)
// projected through an ordinary barrel lens that OpenCV's 5-coefficient
// model describes exactly, so both solve the same model (poly6 = k1 k2 k3
// p1 p2) and must reach the same RMS. Ratios are measured in one run.
// Then (issue #14) the whole --knots auto choice (every count tried, each
// 5-fold cross-validated) against one fixed-knot B-spline solve (13
// coefficients, no cross-validation) and against cv::calibrateCamera on the
// same detections, on the mustache lens (models of synthetic_rig.h).
//
//   build/bench/bench_calib [--repeats N] [--auto-only]
#include <CLI/CLI.hpp>
#include <cstdio>
#include <functional>
#include <opencv2/calib3d.hpp>
#include <vector>

#include "bench_support.h"
#include "calib/calibrate.h"
#include "synthetic_rig.h"

namespace {

// The median wall time of `repeats` runs of `run`.
double MedianSeconds(int repeats, const std::function<void()>& run) {
  std::vector<double> seconds;
  for (int i = 0; i < repeats; ++i) seconds.push_back(ws::bench::Milliseconds(run) / 1000);
  return ws::bench::Median(seconds);
}

// A 1280 x 960 camera with fx = 900 and moderate barrel distortion (about
// 70 degrees across), poly6 with tangential terms: OpenCV's own model.
ws::CameraModel BenchCamera() {
  ws::CameraModel camera;
  camera.image_width = 1280;
  camera.image_height = 960;
  camera.fx = 900;
  camera.fy = 901;
  camera.cx = 643.2;
  camera.cy = 478.9;
  camera.p1 = 3e-4;
  camera.p2 = -2e-4;
  camera.distortion = ws::Distortion{ws::ModelKind::kPoly6, 0, {}, {-0.12, 0.03, -0.004}};
  return camera;
}

// The median time of cv::calibrateCamera (its default 5 coefficients) on
// the camera's views; its RMS into *rms.
double OpenCvSeconds(const ws::calib::CameraData& data, int repeats, double* rms) {
  std::vector<std::vector<cv::Point3f>> object;
  std::vector<std::vector<cv::Point2f>> image;
  for (const auto& view : data.views) {
    object.emplace_back();
    image.emplace_back();
    for (int i = 0; i < view.size(); ++i) {
      object.back().emplace_back(view.object[i].x(), view.object[i].y(), view.object[i].z());
      image.back().emplace_back(view.image[i].x(), view.image[i].y());
    }
  }
  return MedianSeconds(repeats, [&] {
    cv::Mat K, distortion;
    std::vector<cv::Mat> rvecs, tvecs;
    *rms = cv::calibrateCamera(object, image, cv::Size(data.image_width, data.image_height), K,
                               distortion, rvecs, tvecs);
  });
}

// --knots auto against one 13-coefficient solve and cv::calibrateCamera.
void AutoKnots(int repeats) {
  std::printf("\n--knots auto (mustache lens, bspline)\n"
              "%6s %12s %12s %12s %10s %10s %8s %8s\n",
              "views", "opencv [s]", "fixed 13 [s]", "auto [s]", "auto/fixed", "auto/cv", "coeffs",
              "auto rms");
  for (int views : {30, 60}) {
    ws::calib::SyntheticRigOptions rig_options;
    rig_options.left = ws::calib::MustacheTestCamera();
    rig_options.stereo = false;
    rig_options.views = views;
    const ws::calib::SyntheticRig rig = ws::calib::MakeSyntheticRig(rig_options);
    const ws::calib::CameraData& data = rig.data.left;
    double opencv_rms = 0;
    const double opencv_s = OpenCvSeconds(data, repeats, &opencv_rms);
    ws::calib::CalibrationOptions fixed;
    fixed.spline.knots = 13;
    fixed.cv_folds = 0;
    const double fixed_s = MedianSeconds(repeats, [&] { ws::calib::CalibrateCamera(data, fixed); });
    ws::calib::CameraCalibration chosen;
    const double auto_s = MedianSeconds(repeats, [&] {
      chosen = ws::calib::CalibrateCamera(data, ws::calib::CalibrationOptions());
    });
    std::printf("%6d %12.4f %12.4f %12.4f %10.2f %10.2f %8zu %8.4f\n", views, opencv_s, fixed_s,
                auto_s, auto_s / fixed_s, auto_s / opencv_s, chosen.param_names.size() - 6,
                chosen.rms_px);
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("Calibration solve time: widestereo (poly6) against cv::calibrateCamera");
  int repeats = 5;
  app.add_option("--repeats", repeats, "Runs per measurement (the median is reported)")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  bool auto_only = false;
  app.add_flag("--auto-only", auto_only, "Only the --knots auto table");
  CLI11_PARSE(app, argc, argv);
  if (auto_only) {
    AutoKnots(repeats);
    return 0;
  }

  std::printf("%6s %8s %12s %12s %12s %12s %8s %12s %12s\n", "views", "corners", "opencv [s]",
              "ours [s]", "ours,nocov", "ours,no cv", "ratio", "opencv rms", "ours rms");
  for (int views : {15, 30, 60}) {
    ws::calib::SyntheticRigOptions rig_options;
    rig_options.left = BenchCamera();
    rig_options.stereo = false;
    rig_options.views = views;
    rig_options.board_cols = 9;
    rig_options.board_rows = 6;
    rig_options.square = 0.05;
    rig_options.target_extent = 0.8;
    rig_options.min_distance = 0.6;
    rig_options.max_distance = 1.2;
    const ws::calib::SyntheticRig rig = ws::calib::MakeSyntheticRig(rig_options);
    const ws::calib::CameraData& data = rig.data.left;

    double opencv_rms = 0;
    const double opencv_s = OpenCvSeconds(data, repeats, &opencv_rms);
    int corners = 0;
    for (const auto& view : data.views) corners += view.size();
    ws::calib::CalibrationOptions options;
    options.model = ws::ModelKind::kPoly6;
    double ours_rms = 0;
    const double ours_s = MedianSeconds(
        repeats, [&] { ours_rms = ws::calib::CalibrateCamera(data, options).rms_px; });
    options.covariance = false;
    const double nocov_s =
        MedianSeconds(repeats, [&] { ws::calib::CalibrateCamera(data, options); });
    options.covariance = true;
    options.cv_folds = 0;
    const double nocv_s =
        MedianSeconds(repeats, [&] { ws::calib::CalibrateCamera(data, options); });
    std::printf("%6d %8d %12.4f %12.4f %12.4f %12.4f %8.2f %12.5f %12.5f\n", views, corners,
                opencv_s, ours_s, nocov_s, nocv_s, ours_s / opencv_s, opencv_rms, ours_rms);
  }
  std::printf("ratio: ours (with standard deviations and the 5-fold held-out RMS) / "
              "cv::calibrateCamera, median of %d runs\n",
              repeats);
  AutoKnots(repeats);
  return 0;
}
