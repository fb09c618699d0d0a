#include "calib/camera_result.h"

#include <algorithm>
#include <cmath>

#include "calib/solver/stage_log.h"

namespace ws::calib {

CameraCalibration CameraResult(const Problem& problem, int c, const Prepared& p,
                               const SolveOutcome& outcome, const std::string& init_method,
                               const CalibrationOptions& options) {
  const CameraBlock& camera = problem.cameras[c];
  CameraCalibration out;
  out.name = p.name;
  out.model = ToCameraModel(camera, p.width, p.height);
  out.residuals = Residuals(problem, c);
  out.rms_px = Rms(out.residuals);
  out.view_rms = ViewRms(out.residuals, static_cast<int>(p.views.size()));
  for (const auto& r : out.residuals) (r.outlier ? out.outliers : out.points)++;
  out.board_poses.assign(p.views.size(), Pose());
  for (const Observation& o : problem.observations) {
    if (o.camera != c) continue;
    ++out.views;
    out.board_poses[o.view] = BoardPose(problem, o);
  }
  out.max_observed_radius = RequireUnfolded(problem, c, p.name);
  if (out.views < options.min_views)
    throw CalibrationError(p.name + " camera: only " + std::to_string(out.views) +
                           " views fit the solved camera, at least " +
                           std::to_string(options.min_views) + " needed");
  out.skipped = p.skipped;
  for (const auto& [left_out_camera, view] : problem.left_out)
    if (left_out_camera == c)
      out.skipped.push_back("view " + std::to_string(view) +
                            ": left out, its corners do not project under the solved camera");
  out.invalid_points = p.invalid_points;
  out.param_names = ParamNames(camera);
  out.stddev = outcome.stddev_camera[c];
  std::vector<Eigen::Vector2d> inlier_corners;
  for (const auto& r : out.residuals)
    if (!r.outlier) inlier_corners.push_back(r.observed);
  out.uncertainty = MapProjectionUncertainty(camera, outcome.covariance_camera[c], p.width,
                                             p.height, inlier_corners);
  out.board_warp = problem.warp;
  out.board_warp_stddev = outcome.stddev_warp;
  out.init_method = init_method;
  out.grid =
      MakeResidualGrid(out.residuals, p.width, p.height, options.grid_rows, options.grid_cols);
  return out;
}

double RequireUnfolded(const Problem& problem, int c, const std::string& name) {
  const CameraBlock& camera = problem.cameras[c];
  double reach = 0;
  for (const Observation& o : problem.observations) {
    if (o.camera != c) continue;
    const Pose pose = BoardPose(problem, o);
    for (int i = 0; i < o.corners->size(); ++i)
      if ((*o.inliers)[i]) reach = std::max(reach, IdealRadius(camera, pose * o.corners->object[i]));
  }
  if (const auto fold = FoldRadius(camera, reach)) {
    // A pinhole radius r = tan(theta) runs to infinity at 90 degrees: a
    // curve in r that must flatten towards it folds first.
    const std::string fisheye =
        Traits(KindOf(camera.model)).angle
            ? ""
            : "; the fold is " + Fixed(std::atan(*fold) * 180 / M_PI, 0) +
                  " degrees off axis, and a pinhole-radius model cannot follow a lens whose "
                  "views reach towards 90 degrees: bspline_theta or kb4 can";
    throw CalibrationError(name + " camera (" + ModelName(KindOf(camera.model)) +
                           "): the solved distortion curve folds back at r = " + Fixed(*fold, 3) +
                           ", inside the observed field; the views do not constrain the model "
                           "(more views, fewer knots or a stronger smoothness prior" + fisheye + ")");
  }
  return reach;
}

void SetHeldOut(const CrossValidation& cv, int camera, CameraCalibration* out) {
  if (cv.folds == 0) return;
  out->heldout_rms_px = cv.rms_px[camera];
  out->heldout_fold_rms_px = cv.fold_rms_px[camera];
  out->heldout_extrapolated = cv.extrapolated[camera];
  out->heldout_corners.clear();
  for (HeldOutCorner h : cv.corners)
    if (h.camera == camera) {
      h.camera = 0;
      out->heldout_corners.push_back(h);
    }
}

}  // namespace ws::calib
