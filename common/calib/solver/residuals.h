// The reprojection residuals of paper Eq. 10 as Ceres cost functions, written
// once for every distortion model (the model concept of models/distortion.h).
//
// One residual block holds the corners of one view (2 residuals per corner:
// projected minus observed pixel), so that the solver sees a few hundred
// blocks instead of thousands; with a robust loss each corner is its own
// block, since Ceres applies a loss to a whole block.
//
// Parameter blocks (all double arrays owned by the caller), in this order:
//   intrinsics[6]  {fx, fy, cx, cy, p1, p2}         (models/projection.h)
//   radial[N]      the model's estimated coefficients (N = model.NumCoeffs())
//   warp[2]        the board's deflection {x2, y2} (board_warp.h), usually held at 0
//   pose[6]        board -> camera (pose.h)
//   extrinsic[6]   left camera -> right camera, X_right = R X_left + T (stereo)
//   tilt[2]        tau_x, tau_y, where the non-radial part has a sensor tilt
//   segments       the non-radial field's segments the view's corners read
//                  (field_blocks.h), in order
//
// The derivatives are automatic (Ceres Jets) and exact, but a corner is not
// differentiated by every coefficient: its residual reads only the model's
// local coefficients at its ideal point (distortion.h; a cubic spline's 4,
// however many knots it has), so the Jet carries those and the fixed-size
// blocks, and their derivatives go to their columns of the coefficient
// block (the other columns are 0). The Jet's size, and so the cost per
// corner, does not grow with the number of knots. A sensor tilt
// (models/sensor_tilt.h) carries its two angles in the Jet. The non-radial
// field (models/nonradial_field.h) is linear in its coefficients: a
// corner's 16 control points and its field's gradient come from its local
// basis, and the chain rule takes the Jet of the tilted point x_t through
// x_t + F(x_t).
#pragma once

#include <ceres/cost_function.h>
#include <ceres/jet.h>
#include <ceres/rotation.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <type_traits>
#include <utility>
#include <vector>

#include "calib/solver/field_blocks.h"
#include "models/model_registry.h"
#include "models/projection.h"
#include "models/scalar_part.h"

namespace ws::calib {

// Corners of one view flattened for the cost functions.
struct ViewPoints {
  std::vector<double> object;  // 3 per corner
  std::vector<double> image;   // 2 per corner
  std::vector<double> warp;    // 2 per corner: the corner's WarpBasis (board_warp.h)
  // A corner whose ideal radius exceeds this makes the evaluation fail, so
  // that the solver never takes a step into the region where a distortion
  // curve may fold back (a corner seen inside the image cannot lie beyond the
  // image's largest ideal radius).
  double max_radius = 1e6;
  int size() const { return static_cast<int>(image.size() / 2); }
  void Add(const Eigen::Vector3d& X, const Eigen::Vector2d& x, const Eigen::Vector2d& basis) {
    object.insert(object.end(), {X.x(), X.y(), X.z()});
    image.insert(image.end(), {x.x(), x.y()});
    warp.insert(warp.end(), {basis.x(), basis.y()});
  }
};

// One view's corners as a cost over (intrinsics, radial, warp, pose) or,
// with kViaExtrinsic, (intrinsics, radial, warp, pose, extrinsic): a board
// posed in the left camera's frame seen by the right camera,
// X_right = R_e (R_b X + t_b) + T_e; then the tilt and the field's segments
// `segments` (above). L >= model.NumLocalCoeffs() is the Jet's room for the
// local coefficients. Evaluate fails if a corner has no projection (a
// pinhole model: behind the camera), its ideal radius (radial_coordinate.h)
// exceeds points.max_radius, or it reads a control point of a segment the
// view was not given.
//
// The chain rule is split at the ideal point (x, y): the rig's blocks (warp,
// pose, extrinsic) reach the pixel only through it, so one Jet carries them
// to (x, y) and another carries (x, y), the intrinsics and the local
// coefficients to the pixel; d pixel / d rig = d pixel / d(x, y) . d(x, y) / d rig.
template <class Model, bool kViaExtrinsic, int L>
class ViewCost final : public ceres::CostFunction {
 public:
  // Keeps pointers to `model` and `field`.
  ViewCost(const Model& model, const NonRadialField& field, ViewPoints points,
           std::vector<int> segments)
      : model_(&model), field_(&field), blocks_(field), points_(std::move(points)),
        segments_(std::move(segments)) {
    set_num_residuals(2 * points_.size());
    for (int size : {int(kNumIntrinsics), model.NumCoeffs(), 2, 6}) AddBlock(size);
    if (kViaExtrinsic) AddBlock(6);
    tilt_at_ = field.tilt() ? AddBlock(2) : -1;
    slot_.assign(size_t(blocks_.count()), -1);
    for (int segment : segments_) slot_[size_t(segment)] = AddBlock(blocks_.Size(segment));
  }

  bool Evaluate(double const* const* p, double* residuals, double** jacobians) const override {
    const int n = model_->NumCoeffs(), local = model_->NumLocalCoeffs();
    std::vector<double> gathered;
    const double* all = field_->empty() ? p[1] : Gather(p, &gathered);
    if (jacobians == nullptr) {
      double R[9], t[3], ideal[2];
      BoardToCamera(p[3], kViaExtrinsic ? p[4] : nullptr, R, t);
      for (int i = 0; i < points_.size(); ++i) {
        if (!Ideal(i, p[2], R, t, ideal)) return false;
        ProjectIdeal(*model_, *field_, p[0], all, ideal, residuals + 2 * i);
        residuals[2 * i] -= points_.image[2 * i];
        residuals[2 * i + 1] -= points_.image[2 * i + 1];
        if (!std::isfinite(residuals[2 * i]) || !std::isfinite(residuals[2 * i + 1])) return false;
      }
      return true;
    }
    const int rows = num_residuals();
    for (size_t b = 1; b < parameter_block_sizes().size(); ++b)
      if (jacobians[b] && int(b) != 2 && int(b) != 3 && !(kViaExtrinsic && b == 4))
        std::fill(jacobians[b], jacobians[b] + rows * parameter_block_sizes()[b], 0.0);
    RigJet warp[2], pose[6], extrinsic[6], R[9], t[3];
    Seed(p[2], 2, kWarpAt, warp);
    Seed(p[3], 6, kPoseAt, pose);
    if (kViaExtrinsic) Seed(p[4], 6, kExtrinsicAt, extrinsic);
    BoardToCamera(pose, kViaExtrinsic ? extrinsic : nullptr, R, t);
    LensJet intrinsics[kNumIntrinsics];
    Seed(p[0], kNumIntrinsics, kIntrinsicsAt, intrinsics);
    const int half = field_->GridCoeffs() / 2;
    const double* field = all + n;
    std::vector<LensJet> coeffs(p[1], p[1] + n);  // constants but for a corner's local ones
    LensJet tau[2];
    if (tilt_at_ >= 0) Seed(p[tilt_at_], 2, kTiltAt, tau);
    for (int i = 0; i < points_.size(); ++i) {
      RigJet ideal[2];
      if (!Ideal(i, warp, R, t, ideal)) return false;
      const int first = model_->FirstLocalCoeff(ideal[0].a, ideal[1].a);
      auto in_range = [&](int j) { return first + j >= 0 && first + j < n; };
      for (int j = 0; j < local; ++j)
        if (in_range(j)) coeffs[first + j].v[kLocalAt + j] = 1.0;
      const LensJet lens_ideal[2] = {LensJet(ideal[0].a, kXAt), LensJet(ideal[1].a, kXAt + 1)};
      LensJet undistorted[2], distorted[2], pixel[2];
      DistortIdeal(*model_, intrinsics, coeffs.data(), lens_ideal, undistorted);
      for (int j = 0; j < local; ++j)
        if (in_range(j)) coeffs[first + j].v[kLocalAt + j] = 0.0;
      if (tilt_at_ >= 0) {  // the tilted point, tau_x, tau_y in the Jet
        TiltPoint(tau, undistorted, distorted);
      } else {
        distorted[0] = undistorted[0];
        distorted[1] = undistorted[1];
      }
      NonRadialField::Local basis{};
      if (field_->grid()) {  // x_t + F(x_t), F linear about the corner's x_t
        basis = field_->LocalBasis(distorted[0].a, distorted[1].a);
        double f[2] = {0, 0}, by_s[2] = {0, 0}, by_t[2] = {0, 0};
        for (int k = 0; k < NonRadialField::kLocal; ++k)
          for (int c = 0; c < 2; ++c) {
            const double coeff = field[c * half + basis.index[k]];
            f[c] += coeff * basis.weight[k];
            by_s[c] += coeff * basis.by_s[k];
            by_t[c] += coeff * basis.by_t[k];
          }
        if (!std::isfinite(f[0]) || !std::isfinite(f[1])) return false;  // a segment not given
        const LensJet d[2] = {distorted[0], distorted[1]};
        for (int c = 0; c < 2; ++c)
          distorted[c] = d[c] + by_s[c] * (d[0] - d[0].a) + by_t[c] * (d[1] - d[1].a) + f[c];
      }
      ToPixel(intrinsics, distorted, pixel);
      for (int k = 0; k < 2; ++k) {
        const int row = 2 * i + k;
        const LensJet& q = pixel[k];
        residuals[row] = q.a - points_.image[row];
        if (double* J = jacobians[0]) std::copy_n(&q.v[kIntrinsicsAt], kNumIntrinsics, J + row * kNumIntrinsics);
        if (double* J = jacobians[1])
          for (int j = 0; j < local; ++j)
            if (in_range(j)) J[row * n + first + j] = q.v[kLocalAt + j];
        // d pixel_k / d c^k_ij = f_k N_i M_j (fx or fy).
        for (int j = 0; j < NonRadialField::kLocal && field_->grid(); ++j) {
          const int segment = blocks_.SegmentOf(k, basis.index[j]);
          if (double* J = jacobians[slot_[size_t(segment)]])
            J[row * blocks_.Size(segment) + blocks_.PositionOf(basis.index[j])] =
                intrinsics[k == 0 ? kFx : kFy].a * basis.weight[j];
        }
        if (tilt_at_ >= 0 && jacobians[tilt_at_]) std::copy_n(&q.v[kTiltAt], 2, jacobians[tilt_at_] + row * 2);
        const RigJet by_rig = q.v[kXAt] * ideal[0] + q.v[kXAt + 1] * ideal[1];
        Scatter(by_rig, kWarpAt, 2, row, jacobians[2]);
        Scatter(by_rig, kPoseAt, 6, row, jacobians[3]);
        if (kViaExtrinsic) Scatter(by_rig, kExtrinsicAt, 6, row, jacobians[4]);
      }
    }
    return true;
  }

 private:
  // The rig's blocks in one Jet, (x, y), the intrinsics and the local
  // coefficients in the other.
  static constexpr int kWarpAt = 0, kPoseAt = 2, kExtrinsicAt = 8;
  using RigJet = ceres::Jet<double, kViaExtrinsic ? 14 : 8>;
  static constexpr int kXAt = 0, kIntrinsicsAt = 2, kLocalAt = kIntrinsicsAt + kNumIntrinsics;
  static constexpr int kTiltAt = kLocalAt + L;  // tau_x, tau_y (a sensor tilt)
  using LensJet = ceres::Jet<double, kTiltAt + 2>;

  // Adds a parameter block; returns its index.
  int AddBlock(int size) {
    mutable_parameter_block_sizes()->push_back(size);
    return int(parameter_block_sizes().size()) - 1;
  }

  // The model's and the field's coefficients in one array, as ProjectIdeal
  // reads them, into *all: the radial block, the view's segments, the tilt;
  // the control points of segments the view was not given are NaN, so a
  // corner that reads one fails the evaluation. Returns all->data().
  const double* Gather(double const* const* p, std::vector<double>* all) const {
    const int n = model_->NumCoeffs();
    all->assign(size_t(n + field_->NumCoeffs()), NAN);
    std::copy_n(p[1], n, all->begin());
    for (int segment : segments_)
      std::copy_n(p[slot_[size_t(segment)]], blocks_.Size(segment),
                  all->begin() + n + blocks_.Offset(segment));
    if (tilt_at_ >= 0) std::copy_n(p[tilt_at_], 2, all->begin() + n + field_->GridCoeffs());
    return all->data();
  }

  template <class Jet>
  static void Seed(const double* values, int size, int at, Jet* out) {
    for (int j = 0; j < size; ++j) out[j] = Jet(values[j], at + j);
  }
  // d value / d block, row `row` of the row-major Jacobian of a block of `size`.
  static void Scatter(const RigJet& value, int at, int size, int row, double* jacobian) {
    if (jacobian == nullptr) return;  // a constant block
    std::copy_n(&value.v[at], size, jacobian + row * size);
  }

  // Board -> camera: the pose's, then (kViaExtrinsic) the extrinsic's.
  template <typename T>
  static void BoardToCamera(const T* pose, const T* extrinsic, T* R, T* t) {
    ceres::AngleAxisToRotationMatrix(pose, ceres::RowMajorAdapter3x3(R));
    std::copy(pose + 3, pose + 6, t);
    if (!kViaExtrinsic) return;
    T Re[9], Rb[9];
    std::copy(R, R + 9, Rb);
    ceres::AngleAxisToRotationMatrix(extrinsic, ceres::RowMajorAdapter3x3(Re));
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c)
        R[3 * r + c] = Re[3 * r] * Rb[c] + Re[3 * r + 1] * Rb[3 + c] + Re[3 * r + 2] * Rb[6 + c];
      t[r] = Re[3 * r] * pose[3] + Re[3 * r + 1] * pose[4] + Re[3 * r + 2] * pose[5] +
             extrinsic[3 + r];
    }
  }

  // The ideal point of corner i displaced by the board's warp, through R, t;
  // false where the coordinate has none or it lies beyond max_radius.
  template <typename T>
  bool Ideal(int i, const T* warp, const T* R, const T* t, T* ideal) const {
    const double* X = &points_.object[3 * i];
    const T z = X[2] + warp[0] * points_.warp[2 * i] + warp[1] * points_.warp[2 * i + 1];
    T camera[3];
    for (int r = 0; r < 3; ++r)
      camera[r] = R[3 * r] * X[0] + R[3 * r + 1] * X[1] + R[3 * r + 2] * z + t[r];
    return Model::Coordinate::Ideal(camera, ideal) &&
           std::hypot(ScalarPart(ideal[0]), ScalarPart(ideal[1])) <= points_.max_radius;
  }

  const Model* model_;
  const NonRadialField* field_;
  FieldBlocks blocks_;
  ViewPoints points_;
  std::vector<int> segments_;
  int tilt_at_ = -1;        // the tilt's block, -1: none
  std::vector<int> slot_;   // per segment of the field: its block, -1: not this view's
};

// The cost of one view's corners for any model with its non-radial field
// (ViewCost; via_extrinsic: the board pose is the left camera's; segments:
// the field's the view reads, FieldSupport). The Jet is sized for a cubic
// spline's 4 local coefficients, or the model's bound for any other.
inline ceres::CostFunction* MakeCost(const AnyDistortionModel& model, const NonRadialField& field,
                                     ViewPoints points, bool via_extrinsic,
                                     std::vector<int> segments) {
  return std::visit(
      [&](const auto& m) -> ceres::CostFunction* {
        using Model = std::decay_t<decltype(m)>;
        constexpr int kCubic = 4, kMax = Model::kMaxLocalCoeffs;
        auto make = [&](auto width) -> ceres::CostFunction* {
          constexpr int kWidth = decltype(width)::value;
          if (via_extrinsic)
            return new ViewCost<Model, true, kWidth>(m, field, std::move(points), std::move(segments));
          return new ViewCost<Model, false, kWidth>(m, field, std::move(points), std::move(segments));
        };
        if constexpr (kMax > kCubic)
          if (m.NumLocalCoeffs() <= kCubic) return make(std::integral_constant<int, kCubic>());
        return make(std::integral_constant<int, kMax>());
      },
      model);
}

}  // namespace ws::calib
