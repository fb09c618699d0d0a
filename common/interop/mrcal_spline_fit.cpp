#include "interop/mrcal_spline_fit.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include "interop/foreign_camera.h"
#include "interop/mrcal_spline.h"

namespace ws {
namespace {

// The fit's samples in stereographic u, with the delta each needs.
struct SplineSample {
  double u[2];
  double delta[2];
};

// The knot layout holding every sample's u (2 % margin) with nx knots across.
MrcalSplineConfig Layout(const std::vector<SplineSample>& samples, int nx) {
  double ux = 0, uy = 0;
  for (const SplineSample& s : samples) {
    ux = std::max(ux, std::abs(s.u[0]));
    uy = std::max(uy, std::abs(s.u[1]));
  }
  MrcalSplineConfig config;
  config.nx = nx;
  config.fov_x_deg = int(std::ceil(4.0 * std::atan(1.02 * ux / 2.0) * 180.0 / M_PI));
  config.ny = std::max(4, int(std::ceil(2.0 * 1.02 * uy / config.Spacing())) + 3);
  return config;
}

// Control points minimising sum |delta(u_i) - delta_i|^2 + lambda |second differences|^2.
// A sample touches a 4 x 4 block of knots, so the normal matrix couples a
// knot with those within 3 of it each way: it is summed as 7 x 7 bands.
std::vector<double> Solve(const MrcalSpline& spline, const std::vector<SplineSample>& samples) {
  const MrcalSplineConfig& c = spline.config();
  const int n = c.nx * c.ny;
  std::vector<double> band(size_t(n) * 49, 0.0);
  auto add = [&](int a, int b, double value) {
    band[size_t(a) * 49 + (b / c.nx - a / c.nx + 3) * 7 + (b % c.nx - a % c.nx + 3)] += value;
  };
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n, 2);
  for (const SplineSample& s : samples) {
    int ix, iy;
    double wx[4], wy[4];
    spline.Weights(s.u[0], c.nx, &ix, wx);
    spline.Weights(s.u[1], c.ny, &iy, wy);
    int index[16];
    double weight[16];
    for (int b = 0; b < 4; ++b)
      for (int a = 0; a < 4; ++a) {
        index[4 * b + a] = (iy - 1 + b) * c.nx + ix - 1 + a;
        weight[4 * b + a] = wy[b] * wx[a];
      }
    for (int i = 0; i < 16; ++i) {
      rhs(index[i], 0) += weight[i] * s.delta[0];
      rhs(index[i], 1) += weight[i] * s.delta[1];
      for (int j = 0; j < 16; ++j) add(index[i], index[j], weight[i] * weight[j]);
    }
  }
  const double lambda = 1e-6;
  auto penalise = [&](int a, int b, int d) {  // lambda (c_a - 2 c_b + c_d)^2
    const int at[3] = {a, b, d};
    const double w[3] = {1, -2, 1};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) add(at[i], at[j], lambda * w[i] * w[j]);
  };
  for (int iy = 0; iy < c.ny; ++iy)
    for (int ix = 0; ix < c.nx; ++ix) {
      const int k = iy * c.nx + ix;
      if (ix > 0 && ix + 1 < c.nx) penalise(k - 1, k, k + 1);
      if (iy > 0 && iy + 1 < c.ny) penalise(k - c.nx, k, k + c.nx);
    }
  std::vector<Eigen::Triplet<double>> normal;
  normal.reserve(band.size());
  for (int a = 0; a < n; ++a)
    for (int o = 0; o < 49; ++o)
      if (band[size_t(a) * 49 + o] != 0)
        normal.emplace_back(a, a + (o / 7 - 3) * c.nx + (o % 7 - 3), band[size_t(a) * 49 + o]);
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(normal.begin(), normal.end());
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(A);
  if (solver.info() != Eigen::Success) throw std::runtime_error("mrcal spline fit: singular");
  const Eigen::MatrixXd x = solver.solve(rhs);
  std::vector<double> control(2 * n);
  for (int k = 0; k < n; ++k) {
    control[2 * k] = x(k, 0);
    control[2 * k + 1] = x(k, 1);
  }
  return control;
}

}  // namespace

MrcalSplineFit FitMrcalSpline(const Camera& camera, double target_px) {
  const CameraModel& m = camera.model();
  const double step = std::max(2.0, m.image_width / 200.0);
  const std::vector<FieldSample> fit = FieldSamples(camera, step);
  const std::vector<FieldSample> check = FieldSamples(camera, step / 2);
  if (fit.empty()) throw std::invalid_argument("the camera's observed field is empty");
  std::vector<SplineSample> samples;
  for (const FieldSample& f : fit) {
    SplineSample s;
    if (!Stereographic::Ideal(f.ray.data(), s.u)) continue;
    s.delta[0] = (f.pixel.x() - m.cx) / m.fx - s.u[0];
    s.delta[1] = (f.pixel.y() - m.cy) / m.fy - s.u[1];
    samples.push_back(s);
  }
  MrcalSplineFit best;
  for (int nx : {16, 20, 24, 32, 40, 48, 64}) {
    const MrcalSpline spline(Layout(samples, nx));
    const std::vector<double> control = Solve(spline, samples);
    const ForeignCamera<MrcalSpline> fitted("mrcal", m.image_width, m.image_height, spline,
                                            {m.fx, m.fy, m.cx, m.cy, 0, 0}, control);
    const FitError error = ProjectionError(fitted, check);
    if (best.model.intrinsics.empty() || error.max_px < best.error.max_px) {
      best.model.lensmodel = spline.config().LensModel();
      best.model.intrinsics = {m.fx, m.fy, m.cx, m.cy};
      best.model.intrinsics.insert(best.model.intrinsics.end(), control.begin(), control.end());
      best.model.width = m.image_width;
      best.model.height = m.image_height;
      best.error = error;
    }
    if (best.error.max_px < target_px) break;
  }
  return best;
}

}  // namespace ws
