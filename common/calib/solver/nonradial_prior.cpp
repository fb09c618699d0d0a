#include "calib/solver/nonradial_prior.h"

#include "calib/solver/field_blocks.h"
#include "models/projection.h"

#include <ceres/cost_function.h>
#include <ceres/jet.h>

#include <Eigen/QR>
#include <cstdint>
#include <Eigen/SVD>
#include <algorithm>
#include <vector>

namespace ws::calib {
namespace {

using Dual = ceres::Jet<double, 1>;

// The first-order moves of the tilted point (s, t) (the distorted point
// without a tilt) that the camera's other parameters make
// (nonradial_prior.h), one column each: fx, fy, cx, cy, p1 and p2 where the
// model has them, each radial coefficient, the tilt's two angles where the
// camera has a tilt, and the camera turned about x, y and z. Empty where
// the tilt or the radial model does not invert at (s, t).
template <class Model>
std::vector<Eigen::Vector2d> GaugePatterns(const Model& model, const CameraBlock& camera, double s,
                                           double t) {
  const double* in = camera.intrinsics.data();
  const int n = model.NumCoeffs();
  const NonRadialField& field = camera.field;
  const double* tilt = camera.coeffs.data() + n + field.GridCoeffs();
  const double tilted[2] = {s, t};
  double distorted[2] = {s, t}, ideal[2];
  if (field.tilt() && !UntiltPoint(tilt, tilted, distorted)) return {};
  if (!Undistort(model, camera.coeffs.data(), in[kP1], in[kP2], distorted, ideal)) return {};
  std::vector<Eigen::Vector2d> patterns = {{s, 0}, {0, t}, {1, 0}, {0, 1}};
  std::vector<Dual> intrinsics(in, in + kNumIntrinsics), coeffs(camera.coeffs.begin(),
                                                                camera.coeffs.begin() + n);
  Dual tau[2] = {Dual(field.tilt() ? tilt[0] : 0.0), Dual(field.tilt() ? tilt[1] : 0.0)};
  // The tilted point of an ideal point, as ProjectIdeal has it.
  auto tilted_of = [&](const Dual* ideal_point, Dual* out) {
    Dual d[2];
    DistortIdeal(model, intrinsics.data(), coeffs.data(), ideal_point, d);
    TiltPoint(tau, d, out);
  };
  const Dual dual_ideal[2] = {Dual(ideal[0]), Dual(ideal[1])};
  auto derivative = [&](Dual* parameter) {
    parameter->v[0] = 1;
    Dual d[2];
    tilted_of(dual_ideal, d);
    parameter->v[0] = 0;
    patterns.emplace_back(d[0].v[0], d[1].v[0]);
  };
  if (Model::kTangential)
    for (int k : {kP1, kP2}) derivative(&intrinsics[k]);
  for (int k = 0; k < n; ++k) derivative(&coeffs[k]);
  if (field.tilt())
    for (Dual& angle : tau) derivative(&angle);
  double ray[3];
  if (!Model::Coordinate::Ray(ideal, ray)) return {};
  for (int axis = 0; axis < 3; ++axis) {  // X + omega (e_axis x X), omega the dual part
    Dual turned[3] = {Dual(ray[0]), Dual(ray[1]), Dual(ray[2])};
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;
    turned[a].v[0] = -ray[b];
    turned[b].v[0] = ray[a];
    Dual turned_ideal[2], d[2];
    if (!Model::Coordinate::Ideal(turned, turned_ideal)) return {};
    tilted_of(turned_ideal, d);
    patterns.emplace_back(d[0].v[0], d[1].v[0]);
  }
  return patterns;
}

// e = M c, c the field's coefficients in its segments' blocks (in order,
// `sizes` of them).
class LinearPrior final : public ceres::CostFunction {
 public:
  LinearPrior(Eigen::MatrixXd M, const std::vector<int>& sizes) : M_(std::move(M)) {
    set_num_residuals(int(M_.rows()));
    for (int size : sizes) mutable_parameter_block_sizes()->push_back(size);
  }
  bool Evaluate(double const* const* p, double* residuals, double** jacobians) const override {
    const std::vector<int32_t>& sizes = parameter_block_sizes();
    Eigen::VectorXd c(M_.cols());
    for (size_t b = 0, at = 0; b < sizes.size(); at += size_t(sizes[b]), ++b)
      c.segment(Eigen::Index(at), sizes[b]) = Eigen::Map<const Eigen::VectorXd>(p[b], sizes[b]);
    Eigen::Map<Eigen::VectorXd>(residuals, M_.rows()) = M_ * c;
    if (jacobians == nullptr) return true;
    for (size_t b = 0, at = 0; b < sizes.size(); at += size_t(sizes[b]), ++b)
      if (jacobians[b])
        Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
            jacobians[b], M_.rows(), sizes[b]) = M_.middleCols(Eigen::Index(at), sizes[b]);
    return true;
  }

 private:
  Eigen::MatrixXd M_;
};

}  // namespace

Eigen::MatrixXd NonRadialPrior(const CameraBlock& camera, double lambda) {
  const NonRadialField& field = camera.field;
  const int cols = field.cols(), rows = field.rows(), n = field.GridCoeffs(), half = n / 2;
  const auto& d = field.domain();
  // The gauge: patterns and field values at the samples.
  std::vector<std::vector<Eigen::Vector2d>> patterns;
  std::vector<NonRadialField::Local> bases;
  for (int j = 0; j < 2 * rows; ++j)
    for (int i = 0; i < 2 * cols; ++i) {
      const double s = d[0] + (d[1] - d[0]) * (i + 0.5) / (2 * cols);
      const double t = d[2] + (d[3] - d[2]) * (j + 0.5) / (2 * rows);
      auto g = std::visit([&](const auto& m) { return GaugePatterns(m, camera, s, t); },
                          camera.model);
      if (g.empty()) continue;
      patterns.push_back(std::move(g));
      bases.push_back(field.LocalBasis(s, t));
    }
  const int samples = int(patterns.size());
  Eigen::MatrixXd A(0, n);
  if (samples > 0) {
    const int g = int(patterns.front().size());
    Eigen::MatrixXd G(2 * samples, g), B = Eigen::MatrixXd::Zero(2 * samples, n);
    for (int k = 0; k < samples; ++k) {
      for (int c = 0; c < g; ++c) G.block<2, 1>(2 * k, c) = patterns[k][c];
      for (int l = 0; l < NonRadialField::kLocal; ++l) {
        B(2 * k, bases[k].index[l]) = bases[k].weight[l];
        B(2 * k + 1, half + bases[k].index[l]) = bases[k].weight[l];
      }
    }
    for (int c = 0; c < g; ++c)
      if (G.col(c).norm() > 0) G.col(c).normalize();
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(G, Eigen::ComputeThinU);
    const Eigen::VectorXd& sigma = svd.singularValues();
    int rank = 0;
    while (rank < sigma.size() && sigma(rank) > 1e-9 * sigma(0)) ++rank;
    A = svd.matrixU().leftCols(rank).transpose() * B;
  }
  // Second differences along rows and columns, each component.
  std::vector<Eigen::RowVectorXd> second;
  for (int c = 0; c < 2; ++c)
    for (int j = 0; j < rows; ++j)
      for (int i = 0; i < cols; ++i)
        for (const auto& [di, dj] : {std::pair{1, 0}, std::pair{0, 1}}) {
          if (i + 2 * di >= cols || j + 2 * dj >= rows) continue;
          Eigen::RowVectorXd e = Eigen::RowVectorXd::Zero(n);
          for (int k = 0; k < 3; ++k)
            e(c * half + (j + k * dj) * cols + i + k * di) = k == 1 ? -2.0 : 1.0;
          second.push_back(e);
        }
  const double fx = camera.intrinsics[kFx];
  Eigen::MatrixXd M(n + int(second.size()) + A.rows(), n);
  M.topRows(n) = lambda * fx * Eigen::MatrixXd::Identity(n, n);
  for (size_t k = 0; k < second.size(); ++k) M.row(n + k) = lambda * fx * second[k];
  M.bottomRows(A.rows()) = kGaugeWeight * fx * A;
  // The same cost |M c|^2 = |R c|^2 from R of M = Q R, n rows instead of
  // about 3 n: the solver forms the prior's outer product every iteration.
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(M);
  const int kept = int(std::min(M.rows(), M.cols()));
  return qr.matrixQR().topRows(kept).triangularView<Eigen::Upper>();
}

void AddNonRadialPrior(ceres::Problem& problem, const CameraBlock& camera,
                       const std::vector<double*>& field) {
  if (!camera.field.grid() || camera.field_prior.rows() == 0) return;
  const FieldBlocks blocks(camera.field);
  std::vector<int> sizes;
  for (int s = 0; s < blocks.count(); ++s) sizes.push_back(blocks.Size(s));
  const std::vector<double*> segments(field.begin(), field.begin() + blocks.count());
  problem.AddResidualBlock(new LinearPrior(camera.field_prior, sizes), nullptr, segments);
}

}  // namespace ws::calib
