// A widestereo camera as mrcal's LENSMODEL_SPLINED_STEREOGRAPHIC
// (mrcal_spline.h), for the models mrcal has no exact match of
// (exact_model.h): bspline, bspline_theta, kb4, poly12, and any camera with
// a sensor tilt or a non-radial field.
//
// Fitted where the lens sees: the observed field (field_samples.h: the
// image's pixels whose rays lie within the calibrated field) within the
// lens circle (lens_circle.h: where the model's radial map folds, when it
// does, or, where the calibration's report says, its outermost corner). fx, fy, cx, cy are the camera's own; with them fixed the
// projection is linear in the spline's control points, so they are the
// least-squares fit of delta(u) = (q - c) / f - u, x and y apart, to the
// rays of a grid in u (four to a knot spacing) that the camera projects
// into that region, with a faint penalty on the control points' second
// differences that settles those no sample reaches (beyond the circle the
// spline goes on smoothly). The knots span the region's stereographic
// extent (fov_x_deg the smallest whole degree that holds it, Ny as many
// knots as its height needs at the same spacing) with the densities mrcal's
// users calibrate with: Nx 16, 20, 24 or 30, the first whose worst
// difference over every pixel of the region is below the target. A lens
// none of them follows gets a finer grid (Nx 40 up to 160, the first below
// the target, else the best of all), and the fit says so beside the best
// of theirs and its error, for its user to weigh a grid mrcal's tools are
// not used to against the error of theirs.
#pragma once

#include <optional>

#include "interop/field_samples.h"
#include "interop/lens_circle.h"
#include "interop/mrcal_cameramodel.h"

namespace ws {

// The finest grid mrcal's users calibrate with (its tour's Nx=30_Ny=18).
constexpr int kMrcalUsersFinestNx = 30;
// The worst difference a grid must come within to be taken (docs/export.md).
constexpr double kMrcalSplineTargetPx = 0.01;

struct MrcalSplineFit {
  MrcalCameraModel model;  // extrinsics 0: the caller's
  LensCircle circle;       // where it was fitted, with the observed field
  FitError error;          // over every pixel of the observed field within the circle
  FitError image_error;    // over every pixel of the observed field
  int nx = 0;              // knots across
  // When no grid of mrcal's users' came within the target and a finer one
  // was written: the best of theirs, and its error within the circle.
  struct Grid {
    int nx;
    FitError error;
  };
  std::optional<Grid> users_best;
};

// observed_radius: the calibration's outermost corner (FindLensCircle), or
// infinite when unknown. nx > 0: that many knots across, whatever the
// error. Throws std::invalid_argument when the camera's observed field is
// empty.
MrcalSplineFit FitMrcalSpline(const Camera& camera, double observed_radius = INFINITY, double target_px = kMrcalSplineTargetPx,
                              int nx = 0);

}  // namespace ws
