#include "interop/model_fit.h"

#include <stdexcept>
#include <vector>

#include <ceres/ceres.h>

#include "models/model_registry.h"
#include "models/projection.h"

namespace ws {
namespace {

template <class Model>
struct PixelResidual {
  template <typename T>
  bool operator()(const T* intrinsics, const T* coeffs, T* residual) const {
    const T point[3] = {T(sample.ray.x()), T(sample.ray.y()), T(sample.ray.z())};
    T pixel[2];
    if (!ws::Project(model, NonRadialField(), intrinsics, coeffs, point, pixel)) return false;
    residual[0] = pixel[0] - sample.pixel.x();
    residual[1] = pixel[1] - sample.pixel.y();
    return true;
  }
  Model model;
  FieldSample sample;
};

// Fits Model's N coefficients and the intrinsics, the intrinsics at
// `fixed_intrinsics` and the coefficients at `fixed_coeffs` held at 0.
template <class Model, int N>
ModelFit Fit(const Camera& camera, const LensCircle& circle, const Model& model,
             const std::vector<int>& fixed_intrinsics, const std::vector<int>& fixed_coeffs) {
  const CameraModel& source = camera.model();
  const std::vector<FieldSample> samples = Within(FieldSamples(camera, 8.0), circle);
  if (samples.empty()) throw std::invalid_argument("the camera's observed field within its lens circle is empty");
  double intrinsics[kNumIntrinsics] = {source.fx, source.fy, source.cx, source.cy, 0, 0};
  double coeffs[N] = {};
  ceres::Problem problem;
  for (const FieldSample& sample : samples)
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<PixelResidual<Model>, 2, kNumIntrinsics, N>(
                                 new PixelResidual<Model>{model, sample}),
                             nullptr, intrinsics, coeffs);
  if (!fixed_intrinsics.empty())
    problem.SetManifold(intrinsics, new ceres::SubsetManifold(kNumIntrinsics, fixed_intrinsics));
  if (!fixed_coeffs.empty()) problem.SetManifold(coeffs, new ceres::SubsetManifold(N, fixed_coeffs));
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = 100;
  options.function_tolerance = 1e-12;
  options.parameter_tolerance = 1e-12;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  ModelFit fit;  // the image size and the fitted parameters only: nothing else of the source's
  fit.model.image_width = source.image_width;
  fit.model.image_height = source.image_height;
  fit.model.fx = intrinsics[kFx], fit.model.fy = intrinsics[kFy];
  fit.model.cx = intrinsics[kCx], fit.model.cy = intrinsics[kCy];
  fit.model.p1 = intrinsics[kP1], fit.model.p2 = intrinsics[kP2];
  fit.model.distortion = model.ToData(coeffs);
  const WidestereoProjection fitted(fit.model);
  const std::vector<FieldSample> image = FieldSamples(camera, 4.0);
  fit.error = ProjectionError(fitted, Within(image, circle));
  fit.image_error = ProjectionError(fitted, image);
  return fit;
}

}  // namespace

ModelFit FitSimplerModel(const Camera& camera, const std::string& kind, const LensCircle& circle) {
  if (kind == "kb4") return Fit<Kb4Distortion, 4>(camera, circle, Kb4Distortion(), {kP1, kP2}, {});
  if (kind == "radtan") return Fit<PolyDistortion<3>, 3>(camera, circle, PolyDistortion<3>(), {}, {2});
  throw std::invalid_argument("no fit to '" + kind + "' (kb4, radtan)");
}

}  // namespace ws
