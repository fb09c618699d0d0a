#include "calib/start/initialise.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "calib/solver/stage_log.h"
#include "calib/start/angle_start.h"
#include "models/model_registry.h"
#include "models/projection.h"

namespace ws::calib {

int Prepared::NumUsable() const {
  return static_cast<int>(std::count(usable.begin(), usable.end(), true));
}

void Prepared::Skip(int view, const std::string& why) {
  usable[view] = false;
  skipped.push_back("view " + std::to_string(view) + ": " + why);
}

Prepared Prepare(const CameraData& data, const CalibrationOptions& options) {
  Prepared p;
  p.name = data.name;
  p.width = data.image_width;
  p.height = data.image_height;
  const int n = static_cast<int>(data.views.size());
  p.views.resize(n);
  p.usable.assign(n, false);
  for (int v = 0; v < n; ++v) {
    if (data.views[v].empty()) continue;
    int dropped = 0;
    p.views[v] = CleanView(data.views[v], &dropped);
    p.invalid_points += dropped;
    p.usable[v] = true;
    if (dropped)
      p.skipped.push_back("view " + std::to_string(v) + ": " + std::to_string(dropped) +
                          " non-finite corners dropped");
    const std::string problem = ViewProblem(p.views[v], options.min_points_per_view);
    if (!problem.empty()) p.Skip(v, problem);
  }
  return p;
}

void RequireViews(const Prepared& p, int min_views) {
  if (p.NumUsable() >= min_views) return;
  std::string why;
  for (const auto& line : p.skipped) why += "\n  " + line;
  throw CalibrationError(p.name + " camera: " + std::to_string(p.NumUsable()) +
                         " usable views of the board, at least " + std::to_string(min_views) +
                         " needed (show the board in more positions, tilted differently)" + why);
}

bool HomographyPose(const Init& init, const Prepared& p, int view, const double* intrinsics,
                    Pose* pose) {
  Eigen::Matrix3d K;
  K << intrinsics[kFx], 0, intrinsics[kCx], 0, intrinsics[kFy], intrinsics[kCy], 0, 0, 1;
  *pose = PoseFromHomography(init.homographies[view], K);
  bool in_front = pose->AllFinite();
  for (const auto& X : p.views[view].object) in_front = in_front && (*pose * X).z() > 0;
  return in_front;
}

namespace {

// The minimum spread of the board normals (Zhang's method, and any planar
// calibration, needs the planes not all parallel).
void RequireSpread(const Prepared& p, const std::vector<Pose>& used,
                   const CalibrationOptions& options) {
  const double spread = MaxNormalAngleDeg(used);
  if (spread >= options.min_view_angle_deg) return;
  std::ostringstream msg;
  msg << p.name << " camera: the " << used.size()
      << " views are degenerate, the board planes are all within " << Fixed(spread, 2)
      << " degrees of parallel (at least " << options.min_view_angle_deg
      << " needed); tilt the board by 20-40 degrees in different directions";
  throw CalibrationError(msg.str());
}

// An angle model's start (angle_start.h): every view its lens can pose
// keeps its place.
Init InitializeAngle(Prepared& p, const CalibrationOptions& options, SharedAngleStart* shared) {
  const AngleStartFit start = shared ? shared->Get(p, options.min_views) : AngleStart(p, options.min_views);
  Init init;
  init.pinhole = start.pinhole;
  init.lens = start.lens;
  init.poses = start.poses;
  std::vector<Pose> used;
  for (size_t v = 0; v < p.views.size(); ++v) {
    if (!p.usable[v]) continue;
    if (!start.posed[v]) {
      p.Skip(int(v), "no board pose fits the rays of its corners");
      continue;
    }
    used.push_back(init.poses[v]);
  }
  Say(options, p.name + ": " + init.pinhole.method + " start from " + std::to_string(used.size()) +
                   " views: f " + Fixed(init.pinhole.fx, 2) + " cx " + Fixed(init.pinhole.cx, 2) +
                   " cy " + Fixed(init.pinhole.cy, 2));
  RequireViews(p, options.min_views);
  RequireSpread(p, used, options);
  return init;
}

}  // namespace

Init Initialize(Prepared& p, const CalibrationOptions& options, ModelKind kind,
                SharedAngleStart* shared) {
  if (p.width <= 0 || p.height <= 0)
    throw CalibrationError(p.name + " camera: no image size in the corners");
  if (Traits(kind).angle)
    return InitializeAngle(p, options, shared);
  const int n = static_cast<int>(p.views.size());
  Init init;
  init.homographies.resize(n);
  std::vector<Eigen::Matrix3d> found;
  for (int v = 0; v < n; ++v) {
    if (!p.usable[v]) continue;
    std::vector<Eigen::Vector2d> plane;
    for (const auto& X : p.views[v].object) plane.push_back(X.head<2>());
    const auto H = EstimateHomography(plane, p.views[v].image);
    if (!H) {
      p.Skip(v, "no homography fits its corners");
      continue;
    }
    init.homographies[v] = *H;
    found.push_back(*H);
  }
  RequireViews(p, options.min_views);
  init.pinhole = ZhangIntrinsics(found, p.width, p.height);
  Say(options, p.name + ": " + init.pinhole.method + " start from " + std::to_string(found.size()) +
                   " views: fx " + Fixed(init.pinhole.fx, 2) + " fy " + Fixed(init.pinhole.fy, 2) +
                   " cx " + Fixed(init.pinhole.cx, 2) + " cy " + Fixed(init.pinhole.cy, 2));
  const double intrinsics[kNumIntrinsics] = {
      init.pinhole.fx, init.pinhole.fy, init.pinhole.cx, init.pinhole.cy, 0, 0};
  init.poses.resize(n);
  std::vector<Pose> used;
  for (int v = 0; v < n; ++v) {
    if (!p.usable[v]) continue;
    if (!HomographyPose(init, p, v, intrinsics, &init.poses[v])) {
      p.Skip(v, "its pose from the homography puts the board behind the camera");
      continue;
    }
    used.push_back(init.poses[v]);
  }
  RequireViews(p, options.min_views);
  RequireSpread(p, used, options);
  return init;
}

CameraBlock StartCamera(const Init& init, const Prepared& p, ModelKind kind,
                        const SplineOptions& spline) {
  const PinholeInit& k = init.pinhole;
  CameraBlock camera = PinholeBlock(kind, spline, k.fx, k.fy, k.cx, k.cy);
  if (!Traits(kind).angle || init.lens != StartLens::kPerspective) return camera;
  const double theta_end = std::atan(0.5 * std::hypot(p.width, p.height) / k.fx);
  return WithRadialCurve(
      camera, [](double theta) { return theta > 1e-9 ? std::tan(theta) / theta - 1 : 0.0; },
      theta_end);
}

}  // namespace ws::calib
