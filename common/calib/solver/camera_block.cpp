#include "calib/solver/camera_block.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "calib/solver/nonradial_prior.h"
#include "calib/solver/smoothness_prior.h"
#include "models/projection.h"

namespace ws::calib {
namespace {

// Corners may not wander past this many times r_max during a solve.
constexpr double kMaxRadiusFactor = 1.5;

CalibrationSetup SetupFor(const SplineOptions& spline, double r_max) {
  return CalibrationSetup{r_max, spline.knots.value() - 1, spline.degree};
}

}  // namespace

CameraBlock PinholeBlock(ModelKind kind, const SplineOptions& spline, double fx, double fy, double cx,
                         double cy) {
  CameraBlock camera(MakeCalibrationModel(kind, SetupFor(spline, 1.0)));
  camera.intrinsics = {fx, fy, cx, cy, 0, 0};
  camera.coeffs.assign(std::visit([](const auto& m) { return m.NumCoeffs(); }, camera.model), 0.0);
  camera.pinhole_only = true;
  return camera;
}

CameraBlock WithRadialCurve(CameraBlock camera, const std::function<double(double)>& curve,
                            double r_end) {
  const int samples = 200, n = NumRadialCoeffs(camera);
  std::fill_n(camera.coeffs.begin(), n, 0.0);
  Eigen::MatrixXd A(samples, n);  // dD / d coeffs[j], D affine in them
  Eigen::VectorXd b(samples);
  for (int k = 0; k < samples; ++k) {
    const double r = r_end * (k + 0.5) / samples;
    const double offset = RadialDistortion(camera, r);
    b(k) = curve(r) - offset;
    for (int j = 0; j < n; ++j) {
      camera.coeffs[j] = 1;
      A(k, j) = RadialDistortion(camera, r) - offset;
      camera.coeffs[j] = 0;
    }
  }
  const Eigen::VectorXd x = A.colPivHouseholderQr().solve(b);
  std::copy_n(x.data(), n, camera.coeffs.begin());
  return camera;
}

CameraBlock ForField(const CameraBlock& camera, const SplineOptions& spline, double r_max) {
  CameraBlock out = camera;
  out.fixed = false;
  out.pinhole_only = false;
  out.free_coeffs = -1;
  out.max_radius = kMaxRadiusFactor * r_max;
  std::visit(
      [&](const auto& model) {
        using Model = std::decay_t<decltype(model)>;
        if constexpr (kIsBspline<Model>) {
          const Model to = Model::ForCalibration(SetupFor(spline, r_max));
          CameraBlock refit(to);
          refit.coeffs.assign(to.NumCoeffs(), 0.0);
          out.coeffs = WithRadialCurve(
                           refit, [&](double r) { return RadialDistortion(camera, r); }, r_max)
                           .coeffs;
          out.coeffs.insert(out.coeffs.end(), camera.coeffs.begin() + model.NumCoeffs(),
                            camera.coeffs.end());  // the field stays as it was
          out.model = to;
          out.prior_weight = SmoothnessWeight(spline.smoothness, camera.intrinsics[kFx], r_max);
        }
      },
      camera.model);
  if (out.field.grid()) out.field_prior = NonRadialPrior(out, spline.smoothness);
  return out;
}

CameraBlock WithNonRadialField(const CameraBlock& camera, int cols, int rows, bool tilt,
                               int width, int height, double lambda) {
  const int n = NumRadialCoeffs(camera);
  std::array<double, 2> tau{};  // the camera's tilt carried over, or 0
  if (camera.field.tilt())
    std::copy_n(camera.coeffs.begin() + n + camera.field.GridCoeffs(), 2, tau.begin());
  CameraBlock out = camera;
  out.coeffs.resize(n);
  out.field_prior.resize(0, 0);
  const double* in = camera.intrinsics.data();
  const double margin_u = 0.01 * width, margin_v = 0.01 * height;
  out.field = NonRadialField(cols, rows,
                             {(-0.5 - margin_u - in[kCx]) / in[kFx],
                              (width - 0.5 + margin_u - in[kCx]) / in[kFx],
                              (-0.5 - margin_v - in[kCy]) / in[kFy],
                              (height - 0.5 + margin_v - in[kCy]) / in[kFy]},
                             tilt);
  out.coeffs.resize(n + out.field.GridCoeffs(), 0.0);
  if (tilt) out.coeffs.insert(out.coeffs.end(), tau.begin(), tau.end());
  if (out.field.grid()) out.field_prior = NonRadialPrior(out, lambda);
  return out;
}

double FieldEnd(const CameraBlock& camera) {
  return std::visit(
      [](const auto& m) {
        if constexpr (kIsBspline<std::decay_t<decltype(m)>>) return m.knots().back();
        return 0.0;
      },
      camera.model);
}

std::vector<std::string> ParamNames(const CameraBlock& camera) {
  std::vector<std::string> names{"fx", "fy", "cx", "cy", "p1", "p2"};
  std::visit(
      [&](const auto& m) {
        for (int i = 0; i < m.NumCoeffs(); ++i) names.push_back(m.CoeffName(i));
      },
      camera.model);
  for (int k = 0; k < camera.field.NumCoeffs(); ++k) names.push_back(camera.field.CoeffName(k));
  return names;
}

int NumRadialCoeffs(const CameraBlock& camera) {
  return std::visit([](const auto& m) { return m.NumCoeffs(); }, camera.model);
}

CameraModel ToCameraModel(const CameraBlock& camera, int image_width, int image_height) {
  CameraModel m;
  m.image_width = image_width;
  m.image_height = image_height;
  m.fx = camera.intrinsics[kFx];
  m.fy = camera.intrinsics[kFy];
  m.cx = camera.intrinsics[kCx];
  m.cy = camera.intrinsics[kCy];
  m.p1 = camera.intrinsics[kP1];
  m.p2 = camera.intrinsics[kP2];
  m.distortion = std::visit([&](const auto& model) { return model.ToData(camera.coeffs.data()); },
                            camera.model);
  m.nonradial = camera.field.ToData(camera.coeffs.data() + NumRadialCoeffs(camera));
  return m;
}

bool AllFinite(const CameraBlock& camera) {
  for (double v : camera.intrinsics)
    if (!std::isfinite(v)) return false;
  for (double v : camera.coeffs)
    if (!std::isfinite(v)) return false;
  return camera.intrinsics[kFx] > 0 && camera.intrinsics[kFy] > 0;
}

std::optional<Eigen::Vector2d> ProjectPoint(const CameraBlock& camera, const Eigen::Vector3d& X) {
  Eigen::Vector2d pixel;
  const bool in_front = std::visit(
      [&](const auto& m) {
        return Project(m, camera.field, camera.intrinsics.data(), camera.coeffs.data(), X.data(),
                       pixel.data());
      },
      camera.model);
  if (!in_front) return std::nullopt;
  return pixel;
}

std::optional<Eigen::Vector2d> IdealPoint(const CameraBlock& camera, const Eigen::Vector2d& pixel) {
  Eigen::Vector2d ideal;
  const bool ok = std::visit(
      [&](const auto& m) {
        return IdealOfPixel(m, camera.field, camera.intrinsics.data(), camera.coeffs.data(),
                            pixel.data(), ideal.data());
      },
      camera.model);
  if (!ok) return std::nullopt;
  return ideal;
}

std::optional<Eigen::Vector3d> PixelRay(const CameraBlock& camera, const Eigen::Vector2d& pixel) {
  Eigen::Vector3d ray;
  const bool ok = std::visit(
      [&](const auto& m) {
        return Unproject(m, camera.field, camera.intrinsics.data(), camera.coeffs.data(),
                         pixel.data(), ray.data());
      },
      camera.model);
  if (!ok) return std::nullopt;
  return ray;
}

double RadialDistortion(const CameraBlock& camera, double r) {
  return std::visit([&](const auto& m) { return m.RadialDistortion(camera.coeffs.data(), r); },
                    camera.model);
}

double PixelRadius(const CameraBlock& camera, const Eigen::Vector2d& pixel) {
  return std::hypot(pixel.x() - camera.intrinsics[kCx], pixel.y() - camera.intrinsics[kCy]);
}

double IdealRadius(const CameraBlock& camera, const Eigen::Vector3d& X) {
  return std::visit(
      [&](const auto& m) { return ws::IdealRadius<typename std::decay_t<decltype(m)>::Coordinate>(X.data()); },
      camera.model);
}

double ImageCornerRadius(const CameraBlock& camera, int image_width, int image_height,
                         double fallback) {
  double r = 0;
  for (double u : {-0.5, image_width - 0.5})
    for (double v : {-0.5, image_height - 0.5}) {
      const auto ideal = IdealPoint(camera, Eigen::Vector2d(u, v));
      if (!ideal) return fallback;
      r = std::max(r, ideal->norm());
    }
  return std::isfinite(r) && r > 0 ? r : fallback;
}

std::optional<double> FoldRadius(const CameraBlock& camera, double r_end) {
  double previous = 0;
  for (int k = 1; k <= 256; ++k) {
    const double r = r_end * k / 256;
    const double height = r * (1 + RadialDistortion(camera, r));
    if (!(height > previous)) return r;
    previous = height;
  }
  return std::nullopt;
}

}  // namespace ws::calib
