#include "calib/heldout.h"

#include <cmath>
#include <limits>

#include "calib/pose_fit.h"

namespace ws::calib {

CameraBlock FixedBlock(const CameraModel& model) {
  CameraBlock block(MakeModel(model.distortion, Coefficients::kIdentifiable));
  block.intrinsics = model.Intrinsics();
  block.coeffs = std::visit([&](const auto& m) { return m.EstimatedCoeffs(model.distortion.coeffs); },
                            block.model);
  block.fixed = true;
  return block;
}

HeldOutFit FitHeldOutViews(const CameraModel& model, const CameraData& data, int min_points,
                           const BoardWarp& warp) {
  const CameraBlock camera = FixedBlock(model);
  HeldOutFit fit;
  fit.view_rms.assign(data.views.size(), -1.0);
  double sum = 0;
  for (size_t v = 0; v < data.views.size(); ++v) {
    const BoardView& view = data.views[v];
    if (view.size() < min_points) continue;
    const std::vector<char> all(view.size(), 1);
    double best = std::numeric_limits<double>::infinity();
    for (Pose pose : PlanarPoseCandidates(camera, view, all))
      best = std::min(best, RefinePose(camera, view, all, &pose, warp));
    if (!std::isfinite(best)) continue;
    fit.view_rms[v] = best;
    sum += best * best * view.size();
    fit.points += view.size();
    ++fit.views;
  }
  fit.rms_px = fit.points > 0 ? std::sqrt(sum / fit.points) : 0.0;
  return fit;
}

}  // namespace ws::calib
