// A widestereo camera as mrcal's LENSMODEL_SPLINED_STEREOGRAPHIC
// (mrcal_spline.h), for the models mrcal has no exact match of
// (exact_model.h): bspline, bspline_theta, kb4, poly12.
//
// fx, fy, cx, cy are the camera's own; with them fixed the projection is
// linear in the spline's control points, so they are the least-squares fit
// of delta(u) = (q - c) / f - u, x and y apart, to the rays of a grid in u
// (four to a knot spacing) that the camera projects into its observed field
// (field_samples.h: its image where its rays lie within its calibrated
// field), with a faint penalty on the control points' second differences
// that settles those no sample reaches. The knots span the field's
// stereographic extent (fov_x_deg the smallest whole degree that holds it,
// Ny as many knots as its height needs at the same spacing); Nx grows from
// 16 (to 160) until the worst difference over every pixel of the field is
// below the target (the simulated mustache lens needs 128).
#pragma once

#include "interop/field_samples.h"
#include "interop/mrcal_cameramodel.h"

namespace ws {

struct MrcalSplineFit {
  MrcalCameraModel model;  // extrinsics 0: the caller's
  FitError error;          // over the observed field, pixels
};

// Throws std::invalid_argument when the camera's observed field is empty.
MrcalSplineFit FitMrcalSpline(const Camera& camera, double target_px = 0.01);

}  // namespace ws
