#include "interop/export.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include <Eigen/Geometry>

#include "interop/kalibr_camchain.h"
#include "interop/model_fit.h"
#include "interop/mrcal_cameramodel.h"
#include "interop/mrcal_spline_fit.h"
#include "interop/opencv_stereo_file.h"
#include "interop/ros_camera_info.h"
#include "runtime/atomic_file.h"

namespace ws {
namespace {

// OpenCV's fixed-point remap tables are in 1/32 px: each coordinate within
// 1/64 px of the model's.
constexpr double kMapErrorPx = 0.0221;  // sqrt(2) / 64
constexpr const char* kNames[2] = {"left", "right"};

std::string Px(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g px", value);
  return text;
}

struct Cameras {
  std::vector<const CameraModel*> models;
  Rig rig;
};

Cameras Of(const Rig& file) {
  Cameras c;
  c.models.push_back(&file.left);
  if (!file.mono) c.models.push_back(&file.right);
  c.rig = file;
  return c;
}

std::string Header(const Rig& file, ExportFormat format) {
  return std::string("widestereo calibration (") + ModelName(file.kind()) + ") exported by stereo-export --to " +
         ExportFormatName(format);
}

// The camera's model as the messages name it: "poly6", "poly6 with a
// sensor tilt", "kb4 with a non-radial field".
std::string Described(const CameraModel& m) {
  return ModelName(m.distortion.kind) + (m.nonradial.cols > 0   ? " with a non-radial field"
                                         : m.nonradial.tilted() ? " with a sensor tilt"
                                                                : "");
}

// Where a fitted model was fitted: "within the lens circle (r = 480.2 px
// about the principal point)", or "(all of it: ...)" when the model has none.
std::string FittedRegion(const LensCircle& circle) {
  if (!std::isfinite(circle.radius)) return "(all of it: the model does not fold, no lens circle)";
  char text[96];
  std::snprintf(text, sizeof text, "within the lens circle (r = %.1f px about the principal point)", circle.radius);
  return text;
}

// A fit's errors, where it was fitted and over the whole observed field:
// "1.20 px (RMS 0.31 px) over the 5120 pixels of the observed field within
// the lens circle (...), where it was fitted; 3.4 px (RMS 0.5 px) over all
// 6400 of the observed field".
std::string FitErrors(const FitError& fitted, const LensCircle& circle, const FitError& image) {
  return Px(fitted.max_px) + " (RMS " + Px(fitted.rms_px) + ") over the " + std::to_string(fitted.points) +
         " pixels of the observed field " + FittedRegion(circle) + ", where it was fitted; " + Px(image.max_px) +
         " (RMS " + Px(image.rms_px) + ") over all " + std::to_string(image.points) + " of the observed field";
}

void RequireStereo(const Rig& file, const std::string& why) {
  if (file.mono) throw std::invalid_argument("a one-camera calibration " + why);
}

Rectification PinholeRectification(const Rig& rig) {
  RectifyOptions options;
  options.mode = RectificationMode::kPinhole;
  return BuildRectification(rig, options);
}

void OpenCv(const Rig& file, const std::string& out, ExportReport* report) {
  RequireStereo(file, "has no stereo rectification: use --to ros, kalibr or mrcal");
  const Cameras c = Of(file);
  const Rectification rect = PinholeRectification(c.rig);
  const std::optional<TargetModel> exact[2] = {ExactTargetModel(file.left, ExportFormat::kOpenCv),
                                               ExactTargetModel(file.right, ExportFormat::kOpenCv)};
  std::vector<std::string> comments{Header(file, ExportFormat::kOpenCv)};
  if (exact[0] && exact[1]) {
    report->lines.push_back("left, right: OpenCV's " + exact[0]->name + " model, exactly (K, D)");
  } else {
    report->exact = false;
    report->max_error_px = kMapErrorPx;
    const std::string model = Described(exact[0] ? file.right : file.left);
    report->lines.push_back(model + " is not an OpenCV model: stereo.yaml holds K, R, T, R1, R2, "
                            "P1, P2, Q and no D; the cameras are maps.yml.gz's remap tables (within " +
                            Px(kMapErrorPx) + ", OpenCV's 1/32 px fixed point)");
    comments.push_back("NOT EXACT: " + model + " is not an OpenCV model; no D: rectify with "
                       "maps.yml.gz (cv::remap), not with K and D");
  }
  WriteOpenCvStereoFile(out + "/stereo.yaml", c.rig, rect, exact, comments);
  WriteRectificationMaps(out + "/maps.yml.gz", rect);
  report->files = {"stereo.yaml", "maps.yml.gz"};
}

void Ros(const Rig& file, const std::string& out, ExportReport* report) {
  const Cameras c = Of(file);
  std::vector<std::optional<TargetModel>> exact;
  for (const CameraModel* m : c.models) exact.push_back(ExactTargetModel(*m, ExportFormat::kRos));
  const bool all_exact = std::all_of(exact.begin(), exact.end(), [](const auto& e) { return e.has_value(); });
  if (!all_exact)
    RequireStereo(file, "of a " + Described(file.left) + " camera has neither a ROS model nor a rectification: "
                        "use --to mrcal or kalibr");
  std::optional<Rectification> rect;
  if (!file.mono) rect = PinholeRectification(c.rig);
  for (size_t i = 0; i < c.models.size(); ++i) {
    const CameraModel& m = *c.models[i];
    RosCameraInfo info;
    info.name = kNames[i];
    std::vector<std::string> comments{Header(file, ExportFormat::kRos)};
    const cv::Matx33d K(m.fx, 0, m.cx, 0, m.fy, m.cy, 0, 0, 1);
    if (rect) {
      const double tx = i == 0 ? 0 : -rect->f * rect->baseline;
      info.P = cv::Matx34d(rect->f, 0, rect->cx, tx, 0, rect->f, rect->cy, 0, 0, 0, 1, 0);
    } else {
      info.P = cv::Matx34d(m.fx, 0, m.cx, 0, 0, m.fy, m.cy, 0, 0, 0, 1, 0);
    }
    if (all_exact) {
      info.width = m.image_width, info.height = m.image_height;
      info.K = K;
      info.distortion_model = exact[i]->name;
      info.D = exact[i]->coeffs;
      info.R = rect ? (i == 0 ? rect->R_left : rect->R_right) : cv::Matx33d::eye();
      report->lines.push_back(info.name + ": ROS's " + info.distortion_model + ", exactly");
    } else {
      info.width = rect->size.width, info.height = rect->size.height;
      info.K = info.P.get_minor<3, 3>(0, 0);
      info.distortion_model = "plumb_bob";
      info.D.assign(5, 0.0);
      info.R = cv::Matx33d::eye();
      // A camera ROS has a model for is rectified too when its pair has none.
      const size_t inexact = exact[i] ? 1 - i : i;
      const std::string not_ros = (exact[i] ? std::string("the ") + kNames[inexact] + " camera's " : "") +
                                  Described(*c.models[inexact]) + " is not a ROS distortion model";
      comments.push_back("NOT THE RAW CAMERA: " + not_ros + ". This is the " + info.name +
                         " rectified camera: remap the raw images with maps.yml.gz (cv::remap, map1_" + info.name +
                         ", map2_" + info.name + ") and publish those");
      report->lines.push_back(info.name + ": " + not_ros + ": wrote the rectified camera; remap the raw images " +
                              "with maps.yml.gz first (within " + Px(kMapErrorPx) + ")");
    }
    WriteRosCameraInfo(out + "/" + info.name + ".yaml", info, comments);
    report->files.push_back(info.name + ".yaml");
  }
  if (!all_exact) {
    report->exact = false;
    report->max_error_px = kMapErrorPx;
    WriteRectificationMaps(out + "/maps.yml.gz", *rect);
    report->files.push_back("maps.yml.gz");
  }
}

void Kalibr(const Rig& file, const std::string& out, const std::array<double, 2>& observed_radius,
            ExportReport* report) {
  const Cameras c = Of(file);
  std::vector<CameraModel> fitted(c.models.size());
  std::vector<KalibrCamera> cameras;
  std::vector<std::string> comments{Header(file, ExportFormat::kKalibr)};
  for (size_t i = 0; i < c.models.size(); ++i) {
    const CameraModel& m = *c.models[i];
    if (auto exact = ExactTargetModel(m, ExportFormat::kKalibr)) {
      cameras.push_back({&m, *exact});
      report->lines.push_back(std::string(kNames[i]) + ": Kalibr's pinhole-" + exact->name + ", exactly");
      continue;
    }
    const Camera camera(m);
    const std::string kind = camera.IsAngleModel() ? "kb4" : "radtan";
    const LensCircle circle = FindLensCircle(camera, observed_radius[i]);
    const ModelFit fit = FitSimplerModel(camera, kind, circle);
    fitted[i] = fit.model;
    cameras.push_back({&fitted[i], *ExactTargetModel(fit.model, ExportFormat::kKalibr)});
    report->exact = false;
    report->max_error_px = std::max(report->max_error_px, fit.error.max_px);
    const std::string what = std::string(kNames[i]) + ": " + Described(m) +
                             " is not a Kalibr model: wrote the closest pinhole-" +
                             cameras.back().distortion.name + ", off by up to " +
                             FitErrors(fit.error, circle, fit.image_error);
    report->lines.push_back(what);
    comments.push_back("NOT EXACT: " + what);
  }
  WriteKalibrCamchain(out + "/camchain.yaml", cameras, file.R, file.T, comments);
  report->files = {"camchain.yaml"};
}

// When the spline needed a finer grid than mrcal's users calibrate with:
// "; no grid mrcal's users calibrate with (Nx 16 to 30) follows it within
// 0.01 px: the best of them, Nx 24, is 1.38 px off (RMS 0.04 px) there;
// this is Nx 128 (--mrcal-nx 24 writes Nx 24)", else "".
std::string FinerGrid(const MrcalSplineFit& fit) {
  if (!fit.users_best) return "";
  const std::string users = std::to_string(fit.users_best->nx);
  return "; no grid mrcal's users calibrate with (Nx 16 to " + std::to_string(kMrcalUsersFinestNx) +
         ") follows it within " + Px(kMrcalSplineTargetPx) + ": the best of them, Nx " + users + ", is " +
         Px(fit.users_best->error.max_px) + " off (RMS " + Px(fit.users_best->error.rms_px) + ") there; this is Nx " +
         std::to_string(fit.nx) + " (--mrcal-nx " + users + " writes Nx " + users + ")";
}

void Mrcal(const Rig& file, const std::string& out, const std::array<double, 2>& observed_radius, int nx,
           ExportReport* report) {
  const Cameras c = Of(file);
  for (size_t i = 0; i < c.models.size(); ++i) {
    const CameraModel& m = *c.models[i];
    std::vector<std::string> comments{Header(file, ExportFormat::kMrcal)};
    MrcalCameraModel model;
    if (auto exact = ExactTargetModel(m, ExportFormat::kMrcal)) {
      model.lensmodel = exact->name;
      model.intrinsics = {m.fx, m.fy, m.cx, m.cy};
      model.intrinsics.insert(model.intrinsics.end(), exact->coeffs.begin(), exact->coeffs.end());
      model.width = m.image_width, model.height = m.image_height;
      report->lines.push_back(std::string(kNames[i]) + ": mrcal's " + exact->name + ", exactly");
    } else {
      const MrcalSplineFit fit = FitMrcalSpline(Camera(m), observed_radius[i], kMrcalSplineTargetPx, nx);
      model = fit.model;
      report->exact = false;
      report->max_error_px = std::max(report->max_error_px, fit.error.max_px);
      const std::string what = std::string(kNames[i]) + ": " + Described(m) +
                               " is not an mrcal model: wrote a fitted " + model.lensmodel +
                               ", worst projection difference " +
                               FitErrors(fit.error, fit.circle, fit.image_error) + FinerGrid(fit);
      report->lines.push_back(what);
      comments.push_back("NOT EXACT: " + what);
    }
    if (i == 1) {
      const Eigen::AngleAxisd r(file.R);
      const Eigen::Vector3d w = r.angle() * r.axis();
      model.extrinsics = {w.x(), w.y(), w.z(), file.T.x(), file.T.y(), file.T.z()};
    }
    const std::string name = "camera-" + std::to_string(i) + ".cameramodel";
    WriteMrcalCameraModel(out + "/" + name, model, comments);
    report->files.push_back(name);
  }
}

}  // namespace

ExportReport ExportCalibration(const Rig& file, ExportFormat format, const std::string& out,
                               const std::array<double, 2>& observed_radius, int mrcal_nx) {
  std::error_code error;
  std::filesystem::create_directories(out, error);
  if (!std::filesystem::is_directory(out))
    throw std::runtime_error("cannot create the folder " + out + (error ? ": " + error.message() : ""));
  ExportReport report;
  // The format's files as one set: all of them put in place, or none (a
  // new stereo.yaml never stands beside the old maps).
  OutputSet set;
  switch (format) {
    case ExportFormat::kOpenCv: OpenCv(file, out, &report); break;
    case ExportFormat::kRos: Ros(file, out, &report); break;
    case ExportFormat::kKalibr: Kalibr(file, out, observed_radius, &report); break;
    case ExportFormat::kMrcal: Mrcal(file, out, observed_radius, mrcal_nx, &report); break;
  }
  set.Commit();
  return report;
}

std::array<double, 2> CalibrationReportRadii(const std::string& report, const Rig& file) {
  const auto fail = [&](const std::string& why) { throw std::runtime_error(report + ": " + why); };
  std::ifstream in(report);
  if (!in) fail("cannot read it");
  const nlohmann::json json = nlohmann::json::parse(in, nullptr, false);
  if (json.is_discarded() || !json.is_object()) fail("not a JSON object (stereo-calibrate's report)");
  // One model's report, or several's ({"models": [...]}): the file's model's.
  const std::string kind = ModelName(file.kind());
  nlohmann::json entry = json;
  if (json.contains("models") && json["models"].is_array()) {
    entry = nullptr;
    for (const auto& model : json["models"])
      if (model.is_object() && model.value("model", "") == kind) entry = model;
  }
  if (!entry.is_object() || entry.value("model", "") != kind || !entry.contains("cameras") ||
      !entry["cameras"].is_array() || entry["cameras"].size() != (file.mono ? 1u : 2u))
    fail("no report of the calibration's " + kind + " model and its cameras");
  std::array<double, 2> radii{INFINITY, INFINITY};
  const CameraModel* models[2] = {&file.left, &file.right};
  for (size_t i = 0; i < entry["cameras"].size(); ++i) {
    const auto& camera = entry["cameras"][i];
    const double fx = camera.value("fx", 0.0), radius = camera.value("max_observed_radius", 0.0);
    if (!(std::abs(fx - models[i]->fx) <= 1e-9 * models[i]->fx))
      fail(std::string(kNames[i]) + " camera's fx is not the calibration's: the report of another calibration");
    if (!(radius > 0)) fail(std::string(kNames[i]) + " camera: no max_observed_radius");
    radii[i] = radius;
  }
  return radii;
}

}  // namespace ws
