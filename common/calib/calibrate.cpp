#include "calib/calibrate.h"

#include <algorithm>
#include <chrono>

#include "calib/camera_result.h"
#include "calib/mono_solve.h"
#include "calib/stereo_solve.h"
#include "models/model_registry.h"

namespace ws::calib {

void CheckOptions(const CalibrationOptions& options) {
  const auto kinds = ModelKinds();
  if (std::find(kinds.begin(), kinds.end(), options.model) == kinds.end()) {
    std::string known;
    for (const auto& kind : kinds) known += (known.empty() ? "" : ", ") + kind;
    throw CalibrationError("unknown model '" + options.model + "' (known: " + known + ")");
  }
  if (options.knots < 2 || options.knots > 64)
    throw CalibrationError("the B-spline needs 2 to 64 knots, not " +
                           std::to_string(options.knots));
  if (options.min_views < 3) throw CalibrationError("min_views must be at least 3");
  if (!(options.smoothness >= 0)) throw CalibrationError("the smoothness weight must be >= 0");
}

CameraCalibration CalibrateCamera(const CameraData& data, const CalibrationOptions& options) {
  CheckOptions(options);
  MonoState state;
  SolveMono(data, ExtentOf({&data}), options, &state);
  return CameraResult(state.problem, 0, state.prepared, state.outcome,
                      state.init_method, options);
}

StereoCalibration CalibrateStereo(const StereoData& data, const CalibrationOptions& options) {
  CheckOptions(options);
  const auto start = std::chrono::steady_clock::now();
  // No right image at all (not merely no board in it): a one-camera rig.
  const bool mono = data.right.image_width == 0 &&
                    std::all_of(data.right.views.begin(), data.right.views.end(),
                                [](const BoardView& view) { return view.empty(); });
  StereoCalibration result;
  if (mono) {
    result.model = options.model;
    result.mono = true;
    result.left = CalibrateCamera(data.left, options);
  } else {
    result = SolveStereo(data, options);
  }
  result.solve_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

ModelCalibrations CalibrateStereoAllModels(const StereoData& data,
                                           const CalibrationOptions& options,
                                           const std::vector<std::string>& kinds) {
  ModelCalibrations results;
  for (const auto& kind : kinds) {
    CalibrationOptions o = options;
    o.model = kind;
    try {
      results.solved.push_back(CalibrateStereo(data, o));
    } catch (const CalibrationError& e) {
      results.failed.push_back({kind, e.what()});
    }
  }
  if (results.solved.empty() && !results.failed.empty())
    throw CalibrationError(results.failed.front().error);
  return results;
}

std::vector<CornerResidual> Reproject(const CameraModel& model, const CameraData& data,
                                      const std::vector<Pose>& board_poses) {
  const Camera camera(model);
  std::vector<CornerResidual> out;
  for (size_t v = 0; v < data.views.size() && v < board_poses.size(); ++v) {
    const BoardView& view = data.views[v];
    for (int i = 0; i < view.size(); ++i) {
      const auto pixel = camera.Project(board_poses[v] * view.object[i]);
      CornerResidual r;
      r.view = int(v);
      r.index = i;
      r.id = view.ids[i];
      r.observed = view.image[i];
      r.residual = pixel ? Eigen::Vector2d(*pixel - view.image[i]) : Eigen::Vector2d(NAN, NAN);
      out.push_back(r);
    }
  }
  return out;
}

}  // namespace ws::calib
