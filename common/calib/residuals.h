// The reprojection residuals of paper Eq. 10 as Ceres cost functions, written
// once for every distortion model (the model concept of models/distortion.h).
//
// One residual block holds the corners of one view (2 residuals per corner:
// projected minus observed pixel), so that the solver sees a few hundred
// blocks instead of thousands; with a robust loss each corner is its own
// block, since Ceres applies a loss to a whole block.
//
// Parameter blocks (all double arrays owned by the caller):
//   intrinsics[6]  {fx, fy, cx, cy, p1, p2}         (models/projection.h)
//   coeffs[N]      the model's estimated coefficients (N = model.NumCoeffs())
//   pose[6]        board -> camera (pose.h)
//   extrinsic[6]   left camera -> right camera, X_right = R X_left + T (stereo)
//   warp[2]        the board's deflection {x2, y2} (board_warp.h), usually held at 0
//
// The coefficient block's size must be known at compile time for fast
// automatic differentiation: it is for N up to kMaxFixedCoeffs (every poly
// model, and B-splines of up to that many knots); larger splines use Ceres's
// dynamic automatic differentiation, which gives the same numbers more slowly.
#pragma once

#include <ceres/autodiff_cost_function.h>
#include <ceres/dynamic_autodiff_cost_function.h>
#include <ceres/rotation.h>

#include <Eigen/Core>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

#include "models/model_registry.h"
#include "models/projection.h"
#include "models/scalar_part.h"

namespace ws::calib {

inline constexpr int kMaxFixedCoeffs = 24;

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

// Projects the view's corners, displaced by the board's `warp`, through
// `model` after `rotation` (row-major 3x3) and `translation`, writing
// projected - observed. False if a corner
// has no projection (a pinhole model: behind the camera) or its ideal radius
// (radial_coordinate.h) exceeds points.max_radius.
template <class Model, typename T>
bool ViewResiduals(const Model& model, const ViewPoints& points, const T* intrinsics,
                   const T* coeffs, const T* warp, const T* rotation, const T* translation,
                   T* residuals) {
  const int n = points.size();
  for (int i = 0; i < n; ++i) {
    const double* X = &points.object[3 * i];
    const T z = X[2] + warp[0] * points.warp[2 * i] + warp[1] * points.warp[2 * i + 1];
    T camera[3];
    for (int r = 0; r < 3; ++r)
      camera[r] =
          rotation[3 * r] * X[0] + rotation[3 * r + 1] * X[1] + rotation[3 * r + 2] * z + translation[r];
    const double point[3] = {ScalarPart(camera[0]), ScalarPart(camera[1]), ScalarPart(camera[2])};
    if (!(ws::IdealRadius<typename Model::Coordinate>(point) <= points.max_radius)) return false;
    T pixel[2];
    if (!Project(model, intrinsics, coeffs, camera, pixel)) return false;
    residuals[2 * i] = pixel[0] - points.image[2 * i];
    residuals[2 * i + 1] = pixel[1] - points.image[2 * i + 1];
  }
  return true;
}

// Corners seen by a camera whose board pose is a parameter block.
template <class Model>
struct ViewResidual {
  const Model* model;
  ViewPoints points;

  template <typename T>
  bool operator()(const T* intrinsics, const T* coeffs, const T* warp, const T* pose,
                  T* residuals) const {
    T R[9];
    ceres::AngleAxisToRotationMatrix(pose, ceres::RowMajorAdapter3x3(R));
    return ViewResiduals(*model, points, intrinsics, coeffs, warp, R, pose + 3, residuals);
  }
  template <typename T>
  bool operator()(T const* const* p, T* residuals) const {
    return (*this)(p[0], p[1], p[2], p[3], residuals);
  }
};

// Corners seen by the right camera of a board whose pose is given in the left
// camera's frame: X_right = R_e (R_b X + t_b) + T_e.
template <class Model>
struct StereoViewResidual {
  const Model* model;
  ViewPoints points;

  template <typename T>
  bool operator()(const T* intrinsics, const T* coeffs, const T* warp, const T* pose,
                  const T* extrinsic, T* residuals) const {
    T Rb[9], Re[9], R[9], t[3];
    ceres::AngleAxisToRotationMatrix(pose, ceres::RowMajorAdapter3x3(Rb));
    ceres::AngleAxisToRotationMatrix(extrinsic, ceres::RowMajorAdapter3x3(Re));
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c)
        R[3 * r + c] = Re[3 * r] * Rb[c] + Re[3 * r + 1] * Rb[3 + c] + Re[3 * r + 2] * Rb[6 + c];
      t[r] = Re[3 * r] * pose[3] + Re[3 * r + 1] * pose[4] + Re[3 * r + 2] * pose[5] +
             extrinsic[3 + r];
    }
    return ViewResiduals(*model, points, intrinsics, coeffs, warp, R, t, residuals);
  }
  template <typename T>
  bool operator()(T const* const* p, T* residuals) const {
    return (*this)(p[0], p[1], p[2], p[3], p[4], residuals);
  }
};

namespace detail {

// The coefficient counts a model can have, compiled as fixed sizes.
template <class Model>
struct FixedCoeffRange {
  static constexpr int kMin = 1, kMax = kMaxFixedCoeffs;
};
template <int K, class Coordinate>
struct FixedCoeffRange<PolyDistortion<K, Coordinate>> {
  static constexpr int kMin = K, kMax = K;
};

template <class Model, int N, class Make>
ceres::CostFunction* DispatchCoeffs(int n, const Make& make) {
  if constexpr (N > FixedCoeffRange<Model>::kMax) {
    return make(std::integral_constant<int, 0>());  // dynamic
  } else {
    if (n == N) return make(std::integral_constant<int, N>());
    return DispatchCoeffs<Model, N + 1>(n, make);
  }
}

}  // namespace detail

// Cost function of ViewResidual over (intrinsics, coeffs, warp, pose).
template <class Model>
ceres::CostFunction* MakeViewCost(const Model& model, ViewPoints points) {
  using F = ViewResidual<Model>;
  const int residuals = 2 * points.size();
  const int n = model.NumCoeffs();
  return detail::DispatchCoeffs<Model, detail::FixedCoeffRange<Model>::kMin>(
      n, [&](auto size) -> ceres::CostFunction* {
        constexpr int N = decltype(size)::value;
        if constexpr (N == 0) {
          auto* cost = new ceres::DynamicAutoDiffCostFunction<F, 8>(new F{&model, points});
          for (int block : {int(kNumIntrinsics), n, 2, 6}) cost->AddParameterBlock(block);
          cost->SetNumResiduals(residuals);
          return cost;
        } else {
          return new ceres::AutoDiffCostFunction<F, ceres::DYNAMIC, kNumIntrinsics, N, 2, 6>(
              new F{&model, points}, residuals);
        }
      });
}

// Cost function of StereoViewResidual over (intrinsics, coeffs, warp, pose, extrinsic).
template <class Model>
ceres::CostFunction* MakeStereoViewCost(const Model& model, ViewPoints points) {
  using F = StereoViewResidual<Model>;
  const int residuals = 2 * points.size();
  const int n = model.NumCoeffs();
  return detail::DispatchCoeffs<Model, detail::FixedCoeffRange<Model>::kMin>(
      n, [&](auto size) -> ceres::CostFunction* {
        constexpr int N = decltype(size)::value;
        if constexpr (N == 0) {
          auto* cost = new ceres::DynamicAutoDiffCostFunction<F, 8>(new F{&model, points});
          for (int block : {int(kNumIntrinsics), n, 2, 6, 6}) cost->AddParameterBlock(block);
          cost->SetNumResiduals(residuals);
          return cost;
        } else {
          return new ceres::AutoDiffCostFunction<F, ceres::DYNAMIC, kNumIntrinsics, N, 2, 6, 6>(
              new F{&model, points}, residuals);
        }
      });
}

// The cost of one view's corners for any model: ViewResidual, or
// StereoViewResidual when the board pose is the left camera's
// (via_extrinsic). The cost keeps a pointer to `model`.
inline ceres::CostFunction* MakeCost(const AnyDistortionModel& model, ViewPoints points,
                                     bool via_extrinsic) {
  return std::visit(
      [&](const auto& m) -> ceres::CostFunction* {
        return via_extrinsic ? MakeStereoViewCost(m, std::move(points))
                             : MakeViewCost(m, std::move(points));
      },
      model);
}

}  // namespace ws::calib
