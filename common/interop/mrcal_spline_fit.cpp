#include "interop/mrcal_spline_fit.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include "interop/foreign_camera.h"
#include "interop/mrcal_spline.h"

namespace ws {
namespace {

// mrcal's own users' spline densities: its documentation's and tour's
// knots across (LENSMODEL_SPLINED_STEREOGRAPHIC_order=3_Nx=16_Ny=12 .. Nx=30_Ny=18),
// tried in turn until one follows the camera within the target; then,
// for a lens they cannot follow (a wide pinhole lens's steep corners),
// finer ones up to 160 across (a 200-degree lens's field at a few degrees
// to a knot spacing; 800 kB).
constexpr int kKnotsAcross[] = {16, 20, 24, 30, 40, 48, 64, 96, 128, 160};

// The fit's samples in stereographic u, with the delta each needs.
struct SplineSample {
  double u[2];
  double delta[2];
};

// The knot layout holding every u of the observed field (2 % margin) with nx knots across.
MrcalSplineConfig Layout(const Eigen::Vector2d& u_max, int nx) {
  MrcalSplineConfig config;
  config.nx = nx;
  config.fov_x_deg = int(std::ceil(4.0 * std::atan(1.02 * u_max.x() / 2.0) * 180.0 / M_PI));
  config.ny = std::max(4, int(std::ceil(2.0 * 1.02 * u_max.y() / config.Spacing())) + 3);
  return config;
}

// The fit's samples: a grid in u, four to a knot spacing each way, of the
// rays the camera projects into the observed field within the lens circle
// (`inside`) and back. (Pixels evenly spaced
// leave u bare where the lens compresses its field, near a fold at its
// edge: 0.07 px off on fisheye-stereo-ros with samples every 4 px.)
template <class Inside>
std::vector<SplineSample> Samples(const Camera& camera, const MrcalSplineConfig& config, const Inside& inside) {
  const CameraModel& m = camera.model();
  const double step = config.Spacing() / 4;
  const double half_x = 0.5 * (config.nx - 1) * config.Spacing(), half_y = 0.5 * (config.ny - 1) * config.Spacing();
  std::vector<SplineSample> samples;
  for (double uy = -half_y; uy <= half_y; uy += step)
    for (double ux = -half_x; ux <= half_x; ux += step) {
      SplineSample s{{ux, uy}, {0, 0}};
      Eigen::Vector3d ray;
      Stereographic::Ray(s.u, ray.data());
      const auto pixel = camera.Project(ray);
      if (!pixel || !camera.InField(ray) || !inside(*pixel) || pixel->x() < -0.5 || pixel->y() < -0.5 ||
          pixel->x() > m.image_width - 0.5 || pixel->y() > m.image_height - 0.5)
        continue;
      // Past a fold a ray lands on a pixel whose ray is another one.
      const auto back = camera.Unproject(*pixel);
      if (!back || (*back - ray).norm() > 1e-6) continue;
      s.delta[0] = (pixel->x() - m.cx) / m.fx - ux;
      s.delta[1] = (pixel->y() - m.cy) / m.fy - uy;
      samples.push_back(s);
    }
  return samples;
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
  const double lambda = 1e-9;
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

MrcalSplineFit FitMrcalSpline(const Camera& camera, double observed_radius, double target_px, int nx) {
  const CameraModel& m = camera.model();
  MrcalSplineFit best;
  best.circle = FindLensCircle(camera, observed_radius);
  // Every pixel of the observed field; the fit and its error within the lens circle.
  const std::vector<FieldSample> image = FieldSamples(camera, 1.0), field = Within(image, best.circle);
  if (field.empty()) throw std::invalid_argument("the camera's observed field is empty");
  Eigen::Vector2d u_max = Eigen::Vector2d::Zero();
  for (const FieldSample& f : field) {
    Eigen::Vector2d u;
    if (Stereographic::Ideal(f.ray.data(), u.data())) u_max = u_max.cwiseMax(u.cwiseAbs());
  }
  const auto in_circle = [&](const Eigen::Vector2d& pixel) { return best.circle.Contains(pixel); };
  std::vector<int> grids(std::begin(kKnotsAcross), std::end(kKnotsAcross));
  if (nx > 0) grids = {nx};
  std::optional<MrcalSplineFit::Grid> users;  // the best of mrcal's users' grids
  for (int across : grids) {
    const MrcalSpline spline(Layout(u_max, across));
    const std::vector<double> control = Solve(spline, Samples(camera, spline.config(), in_circle));
    const ForeignCamera<MrcalSpline> fitted("mrcal", m.image_width, m.image_height, spline,
                                            {m.fx, m.fy, m.cx, m.cy, 0, 0}, control);
    const FitError error = ProjectionError(fitted, field);
    if (across <= kMrcalUsersFinestNx && (!users || error.max_px < users->error.max_px)) users = {{across, error}};
    if (best.model.intrinsics.empty() || error.max_px < best.error.max_px) {
      best.model.lensmodel = spline.config().LensModel();
      best.model.intrinsics = {m.fx, m.fy, m.cx, m.cy};
      best.model.intrinsics.insert(best.model.intrinsics.end(), control.begin(), control.end());
      best.model.width = m.image_width;
      best.model.height = m.image_height;
      best.error = error;
      best.nx = across;
    }
    if (best.error.max_px < target_px) break;
  }
  if (nx == 0 && best.nx > kMrcalUsersFinestNx) best.users_best = users;
  // The one written, as mrcal reads it, on every pixel within the circle and of the whole field.
  const auto written = MrcalCamera(best.model);
  best.error = ProjectionError(*written, field);
  best.image_error = ProjectionError(*written, image);
  return best;
}

}  // namespace ws
