#include "calib/start/pose_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/calib3d.hpp>

#include "calib/solver/quality.h"
#include "calib/solver/stage_log.h"
#include "calib/start/ray_pose.h"

namespace ws::calib {

double RefinePose(const CameraBlock& camera, const BoardView& view, const std::vector<char>& mask,
                  Pose* pose, const BoardWarp& warp) {
  const Pose before = *pose;
  std::vector<char> inliers = mask;
  Problem one;
  one.cameras.push_back(camera);
  one.cameras[0].fixed = true;
  one.warp = warp;
  one.warp.free = false;
  one.observations.push_back({0, 0, &view, &inliers, pose, false});
  try {
    Solve(one, SolveSettings{"pose", 30});
  } catch (const CalibrationError&) {
    *pose = before;
    return std::numeric_limits<double>::infinity();
  }
  return Rms(Residuals(one, 0));
}

namespace {

// The pose of the view's corners in mask from their rays under the camera.
std::optional<Pose> RayPose(const CameraBlock& camera, const BoardView& view,
                            const std::vector<char>& mask) {
  std::vector<Eigen::Vector3d> object, rays;
  for (int i = 0; i < view.size(); ++i) {
    if (!mask[i]) continue;
    const auto ray = PixelRay(camera, view.image[i]);
    if (!ray) continue;
    object.push_back(view.object[i]);
    rays.push_back(*ray);
  }
  return PoseFromRays(object, rays);
}

// A fresh pose of view v for the camera as it stands: from the homography
// (pinhole models) or from the rays (angle models, which have none).
bool StartPose(const CameraBlock& camera, const Init& init, const Prepared& p, int v,
               const std::vector<char>& mask, Pose* pose) {
  if (!Traits(KindOf(camera.model)).angle) return HomographyPose(init, p, v, camera.intrinsics.data(), pose);
  const auto from_rays = RayPose(camera, p.views[v], mask);
  if (from_rays) *pose = *from_rays;
  return from_rays.has_value();
}

// The distance from the principal point of the farthest corner in mask of
// a view that fits (rms within `bad`): how far the camera is known.
double SupportedRadius(const CameraBlock& camera, const Prepared& p, const Inliers& mask,
                       const std::vector<double>& rms, double bad) {
  double radius = 0;
  for (size_t v = 0; v < p.views.size(); ++v)
    for (int i = 0; i < p.views[v].size() && rms[v] >= 0 && rms[v] <= bad; ++i)
      if (mask[v][i]) radius = std::max(radius, PixelRadius(camera, p.views[v].image[i]));
  return radius;
}

// The outermost boards of a wide lens reach past the field the other views
// support, where the camera as it stands extrapolates and misfits them by
// pixels however right their pose: such a view's pose is fitted on its
// corners within `supported` alone, from *pose, and kept (true) when those
// fit within `bad` and the model can take its other corners (their ideal
// radius finite and within the camera's max_radius: a pinhole radius ends
// at 90 degrees); the solve that follows then carries the camera out to
// them.
bool FitsInsideSupportedField(const CameraBlock& camera, const BoardView& view,
                              const std::vector<char>& mask, double supported, int min_points,
                              double bad, Pose* pose) {
  std::vector<char> inside = mask;
  for (int i = 0; i < view.size(); ++i)
    inside[i] = mask[i] && PixelRadius(camera, view.image[i]) <= supported;
  const auto count = std::count(inside.begin(), inside.end(), 1);
  if (count < min_points || count == std::count(mask.begin(), mask.end(), 1)) return false;
  Pose fitted = *pose;
  if (!(RefinePose(camera, view, inside, &fitted) <= bad)) return false;
  for (int i = 0; i < view.size(); ++i)
    if (mask[i] && !(IdealRadius(camera, fitted * view.object[i]) <= camera.max_radius)) return false;
  *pose = fitted;
  return true;
}

}  // namespace

std::vector<Pose> PlanarPoseCandidates(const CameraBlock& camera, const BoardView& view,
                                       const std::vector<char>& mask) {
  if (Traits(KindOf(camera.model)).angle) {  // ideal points are not pinhole ones
    const auto pose = RayPose(camera, view, mask);
    return pose ? std::vector<Pose>{*pose} : std::vector<Pose>{};
  }
  std::vector<cv::Point3d> object;
  std::vector<cv::Point2d> ideal;
  for (int i = 0; i < view.size(); ++i) {
    if (!mask[i]) continue;
    const auto xy = IdealPoint(camera, view.image[i]);
    if (!xy) continue;
    object.emplace_back(view.object[i].x(), view.object[i].y(), view.object[i].z());
    ideal.emplace_back(xy->x(), xy->y());
  }
  std::vector<Pose> out;
  if (object.size() < 4) return out;
  std::vector<cv::Mat> rvecs, tvecs;
  try {
    cv::solvePnPGeneric(object, ideal, cv::Mat::eye(3, 3, CV_64F), cv::Mat(), rvecs, tvecs, false,
                        cv::SOLVEPNP_IPPE);
  } catch (const cv::Exception&) {
    return out;
  }
  for (size_t k = 0; k < rvecs.size(); ++k) {
    Pose pose;
    for (int j = 0; j < 3; ++j) {
      pose.data[j] = rvecs[k].at<double>(j);
      pose.data[3 + j] = tvecs[k].at<double>(j);
    }
    if (pose.AllFinite()) out.push_back(pose);
  }
  return out;
}

std::vector<bool> RefitPoses(const CameraBlock& camera, const Prepared& p, const Init& init,
                             const Inliers& mask, bool from_homography,
                             const CalibrationOptions& options, const std::string& what,
                             std::vector<Pose>* poses) {
  const int n = static_cast<int>(p.views.size());
  std::vector<double> rms(n, -1.0);  // -1: not refitted
  for (int v = 0; v < n; ++v) {
    if (!p.usable[v] || std::count(mask[v].begin(), mask[v].end(), 1) < options.min_points_per_view)
      continue;
    Pose pose;
    if (from_homography && StartPose(camera, init, p, v, mask[v], &pose)) (*poses)[v] = pose;
    rms[v] = RefinePose(camera, p.views[v], mask[v], &(*poses)[v]);
  }
  std::vector<double> fitted;
  for (double r : rms)
    if (r >= 0 && std::isfinite(r)) fitted.push_back(r);
  std::vector<bool> good(n, true);
  if (fitted.empty()) return good;
  // Corners just outside the disc the camera was fitted on misfit by a few
  // pixels; a wrong pose by tens.
  const double bad = std::max(10 * Median(fitted), 2.0);
  const double supported = SupportedRadius(camera, p, mask, rms, bad);
  for (int v = 0; v < n; ++v) {
    if (!(rms[v] > bad)) continue;
    std::vector<Pose> starts = PlanarPoseCandidates(camera, p.views[v], mask[v]);
    Pose pose;
    if (StartPose(camera, init, p, v, mask[v], &pose)) starts.push_back(pose);
    for (const Pose& start : starts) {
      pose = start;
      const double r = RefinePose(camera, p.views[v], mask[v], &pose);
      if (r < rms[v]) {
        rms[v] = r;
        (*poses)[v] = pose;
      }
    }
    good[v] = rms[v] <= bad || FitsInsideSupportedField(camera, p.views[v], mask[v], supported,
                                                         options.min_points_per_view, bad,
                                                         &(*poses)[v]);
    if (!good[v])
      Say(options, what + ": view " + std::to_string(v) + " fits badly (rms " + Fixed(rms[v], 2) +
                       " px), left out of this stage");
  }
  return good;
}

}  // namespace ws::calib
