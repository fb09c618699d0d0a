// One camera's parameters as the solver holds them: the distortion model
// (any kind of models/model_registry.h), the intrinsics {fx fy cx cy p1 p2}
// and the model's estimated coefficients, each array one Ceres parameter
// block, plus how a solve treats them.
#pragma once

#include <Eigen/Core>
#include <array>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "calib/solver/options.h"
#include "models/camera_model.h"
#include "models/model_registry.h"

namespace ws::calib {

struct CameraBlock {
  explicit CameraBlock(AnyDistortionModel model) : model(std::move(model)) {}

  AnyDistortionModel model;
  NonRadialField field;  // the non-radial part (nonradial_field.h); empty: none
  Eigen::MatrixXd field_prior;  // its prior (nonradial_prior.h), fixed with the field
  std::array<double, kNumIntrinsics> intrinsics{};
  std::vector<double> coeffs;  // model's NumCoeffs(), then field's NumCoeffs()
  bool fixed = false;          // intrinsics and coefficients constant
  bool pinhole_only = false;   // coefficients constant, p1 = p2 = 0 held
  int free_coeffs = -1;        // only coeffs[0 .. free_coeffs) free; -1: all
  double prior_weight = 0;     // smoothness prior (B-splines), pixels
  // A corner whose ideal radius exceeds this fails the evaluation, so a solve
  // never steps where a distortion curve may fold back (ViewPoints).
  double max_radius = 1e6;
};

// A pinhole start: the model of `kind` on the spline's knots over [0, 1]
// with zero coefficients, only fx fy cx cy free (pinhole_only). For an angle
// model (D = 0 over theta) that is the equidistant fisheye, r_pixels = f
// theta. The spline's knots must be a count (not auto): throws
// std::bad_optional_access otherwise.
CameraBlock PinholeBlock(ModelKind kind, const SplineOptions& spline, double fx, double fy, double cx,
                         double cy);

// The same camera with the coefficients of its radial model whose D(r) is
// closest to `curve` over (0, r_end] (least squares at 200 radii); its
// field, if any, as it was. For the models whose D is affine in their
// coefficients (the polynomials and the B-splines).
CameraBlock WithRadialCurve(CameraBlock camera, const std::function<double(double)>& curve,
                            double r_end);

// The same camera with its model (and, for B-splines, knots) for the field
// [0, r_max]: the distortion curve carried over by least squares (B-splines;
// the polynomials need no change), the prior weight and max_radius set for
// r_max, everything free. The spline's knots as for PinholeBlock.
CameraBlock ForField(const CameraBlock& camera, const SplineOptions& spline, double r_max);

// The same camera with a non-radial part (nonradial_field.h): a field of
// cols x rows control points (0 x 0: none) over its image of width x height
// pixels as the camera sees it (the normalized rectangle, 1 % wider each
// side), starting at F = 0, with its prior (nonradial_prior.h) at the
// camera's parameters and the smoothness weight lambda; and, with `tilt`,
// a sensor tilt (the camera's, or 0 if it has none).
CameraBlock WithNonRadialField(const CameraBlock& camera, int cols, int rows, bool tilt,
                               int width, int height, double lambda);

// A B-spline's field end r_max (its last knot); 0 for the polynomials.
double FieldEnd(const CameraBlock& camera);
// fx fy cx cy p1 p2, then the model's coefficient names (alpha2.., k1..),
// then the field's (field_x_0_0..).
std::vector<std::string> ParamNames(const CameraBlock& camera);
// The radial model's estimated coefficients, the first of camera.coeffs.
int NumRadialCoeffs(const CameraBlock& camera);
CameraModel ToCameraModel(const CameraBlock& camera, int image_width, int image_height);
bool AllFinite(const CameraBlock& camera);

// The pixel of a camera-frame point; nullopt behind the camera.
std::optional<Eigen::Vector2d> ProjectPoint(const CameraBlock& camera, const Eigen::Vector3d& X);
// The ideal normalized point of a pixel; nullopt where the model does not
// invert (models/projection.h, Undistort).
std::optional<Eigen::Vector2d> IdealPoint(const CameraBlock& camera, const Eigen::Vector2d& pixel);
// The unit ray of a pixel; nullopt where the model does not invert.
std::optional<Eigen::Vector3d> PixelRay(const CameraBlock& camera, const Eigen::Vector2d& pixel);
// D(r).
double RadialDistortion(const CameraBlock& camera, double r);
// How far a pixel is from the camera's principal point, pixels.
double PixelRadius(const CameraBlock& camera, const Eigen::Vector2d& pixel);
// The ideal radius r of a camera-frame point (tan(theta), or theta for an
// angle model: models/radial_coordinate.h); infinity where it has none.
double IdealRadius(const CameraBlock& camera, const Eigen::Vector3d& X);

// The largest ideal radius of the image's four corners, or `fallback` where
// the model cannot be inverted.
double ImageCornerRadius(const CameraBlock& camera, int image_width, int image_height,
                         double fallback);

// The first radius in (0, r_end] (of 256 steps) where r (1 + D(r)) stops
// increasing, i.e. where the curve folds back; nullopt when it does not.
std::optional<double> FoldRadius(const CameraBlock& camera, double r_end);

}  // namespace ws::calib
