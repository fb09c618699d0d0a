// Camera and stereo calibration (paper Sec. VI-B): Zhang's initialisation,
// then a joint Levenberg-Marquardt (Ceres) over intrinsics, distortion and
// every board pose, minimising the reprojection error (paper Eq. 10), for
// any distortion model of models/model_registry.h.
//
//   calib::CalibrationOptions options;                  // options.h: "bspline", --knots auto, ...
//   calib::StereoCalibration result = calib::CalibrateStereo(data, options);
//   result.left.model   -> a CameraModel (models/camera_model.h)
//   result.R, result.T  -> X_right = R X_left + T
//
// How: mono_solve.h (one camera: Zhang, radial continuation, outliers),
// stereo_solve.cpp (R, T from the stereo pairs, then optionally one joint
// solve), problem.h (the Ceres problem), camera_result.h (the checks).
// Errors: CalibrationError (calib_data.h) saying what is wrong with the
// input, never a result built on garbage.
//
// RMS convention (OpenCV's): sqrt(sum |projected - observed|^2 / corners),
// the root mean square of the corners' pixel distances.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "calib/evaluate/heldout_corner.h"
#include "calib/evaluate/projection_uncertainty.h"
#include "calib/evaluate/selection.h"
#include "calib/solver/board_warp.h"
#include "calib/solver/calib_data.h"
#include "calib/solver/options.h"
#include "calib/solver/pose.h"
#include "calib/solver/quality.h"
#include "models/camera_model.h"

namespace ws::calib {

// One candidate of --knots auto (mono_solve.h): the camera solved with
// `knots` estimated coefficients, its fitted RMS and its cross-validated
// (heldout.h) RMS, overall and per fold.
struct KnotTrial {
  int knots = 0;
  double rms_px = 0;
  double heldout_rms_px = -1;
  std::vector<double> fold_rms_px;
};

// One candidate of --nonradial auto (mono_solve.h): the camera with a sensor
// tilt or not and a field of cols x rows control points (0 x 0: none) with
// its smoothness weight, its fitted and held-out RMS.
struct FieldTrial {
  bool tilt = false;
  int cols = 0, rows = 0;
  double smoothness = 0;  // the field's prior weight lambda (nonradial_prior.h)
  double rms_px = 0;
  double heldout_rms_px = -1;
  std::vector<double> fold_rms_px;
};

// One camera's calibration and its quality.
struct CameraCalibration {
  std::string name;
  CameraModel model;
  double rms_px = 0;                      // over all the camera's inlier corners
  // K-fold cross-validated RMS (heldout.h, CrossValidate) of the final
  // solve, overall and per fold; negative / empty when not computed.
  double heldout_rms_px = -1;
  std::vector<double> heldout_fold_rms_px;
  int heldout_extrapolated = 0;           // held-out corners past the training views' field, left out
  std::vector<HeldOutCorner> heldout_corners;  // camera 0: this one (FoldRmsOnCommonCorners)
  std::vector<KnotTrial> knot_curve;      // --knots auto: every count tried, in order
  std::vector<FieldTrial> field_curve;    // --nonradial auto: none, the tilt, then every field tried
  int field_chosen = 0;                   // its index in field_curve
  int views = 0;                          // views used
  int points = 0;                         // inlier corners used
  int outliers = 0;                       // corners rejected as outliers
  int invalid_points = 0;                 // non-finite corners dropped
  std::vector<double> view_rms;           // per input view; negative: not used
  std::vector<Pose> board_poses;          // per input view, board -> this camera (used views)
  std::vector<std::string> skipped;       // why views were not used ("view 3: ...")
  std::vector<std::string> param_names;   // fx fy cx cy p1 p2, then the model's coefficients
  std::vector<double> stddev;             // same order; empty without covariance
  std::vector<Selection> selections;      // every choice made for this camera (selection.h)
  // 1-sigma projection uncertainty over the image (projection_uncertainty.h);
  // empty without covariance.
  ProjectionUncertainty uncertainty;
  std::string init_method;                // PinholeInit::method (Zhang's, or the angle start's lens)
  BoardWarp board_warp;                   // the board the fit assumed (free: estimated)
  std::vector<double> board_warp_stddev;  // x2, y2; empty without covariance
  WarpChoice warp_choice;                 // --board-warp auto: this camera's views' decision
  double max_observed_radius = 0;         // largest ideal radius of an inlier corner
  std::vector<CornerResidual> residuals;  // every corner, outliers flagged
  ResidualGrid grid;
};

struct StereoCalibration {
  ModelKind model = ModelKind::kBspline;
  // A one-camera rig (no right view at all): `right` empty, no R, T.
  bool mono = false;
  StereoFlow flow = StereoFlow::kJoint;
  CameraCalibration left, right;
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();  // X_right = R X_left + T
  Eigen::Vector3d T = Eigen::Vector3d::Zero();      // metres
  double rms_px = 0;             // over both cameras' inlier corners of the stereo views;
                                 // a one-camera rig: its camera's RMS
  int views = 0;                 // stereo views used
  // Views both cameras saw whose pair fits no rigid rig (a board that moved
  // between the exposures, a misordered right image): out of R, T, each
  // camera keeps its view.
  std::vector<int> inconsistent_views;
  // The joint solve asked for and left out (sharing the board poses
  // worsened the cameras' fit beyond chance: pairs not exposed together):
  // each camera from its own views, flow kPaper.
  bool joint_left_out = false;
  // Views whose right image numbered a symmetric board's corners from the
  // other end (half_turn.h): renumbered, not fitted.
  std::vector<int> half_turned_views;
  std::vector<double> view_rms;  // per input view; negative: not a stereo view
  std::vector<std::string> extrinsic_names;  // rx ry rz tx ty tz
  // Angle-axis radians, metres. In the paper's flow they are those of R, T
  // with the cameras held, so smaller than the joint flow's.
  std::vector<double> extrinsic_stddev;
  double solve_seconds = 0;  // wall clock, not reproducible
};

// Calibrates one camera from its views (empty views are skipped).
CameraCalibration CalibrateCamera(const CameraData& data, const CalibrationOptions& options);

// Calibrates both cameras and R, T. Views seen by one camera only serve that
// camera's intrinsics. Throws CalibrationError when either camera or the
// stereo pairs are not enough. Data whose right camera sent no image at all
// (image size 0) are a one-camera rig: the left camera alone (mono).
StereoCalibration CalibrateStereo(const StereoData& data, const CalibrationOptions& options);

// The outcome of solving the same data with several models.
struct ModelFailure {
  std::string model;
  std::string error;       // CalibrationError's message, or why it was not tried
  bool not_tried = false;  // left out by design (no image of the views), not failed
};
struct ModelCalibrations {
  std::vector<StereoCalibration> solved;  // in the order asked
  std::vector<ModelFailure> failed;
  // The one published and written to --out, by the rule of selection.h
  // (model_selection says how): of the models that use the most views, in
  // order of parameters per camera, their held-out RMS both cameras' folds
  // pooled, on the corners all kept. Where one was not cross-validated (fewer than 4 views),
  // the one of the lowest RMS over the degrees of freedom left,
  // rms sqrt(n / (n - p)), the cameras pooled. With a non-radial field
  // asked for, the models are compared without one and the chosen model is
  // then solved again with it (options.h, FieldRule).
  int chosen = 0;
  Selection model_selection;
  double solve_seconds = 0;  // wall clock of the whole, the models solved at once

};
const StereoCalibration& Chosen(const ModelCalibrations& calibrations);

// "left: 51 corners left out as outliers (Chauvenet's criterion, options.h),
// in views 3 (2), 7 (5), ..."; "" when none were.
std::string OutlierLine(const CameraCalibration& camera);

// "left: projection uncertainty (1 sigma, worst direction) median 0.012 px,
// worst 0.045 px over the 412 observed cells of 32 x 24"
// (projection_uncertainty.h).
std::string UncertaintyLine(const CameraCalibration& camera);

// The held-out RMS of the rig's cameras pooled (their corners weighted
// alike); negative when not computed.
double HeldOutRms(const StereoCalibration& calibration);

// The same data solved with each model kind in turn (Table II and the
// curves), and the one to publish chosen. A model that fails is reported in `failed` and the others are
// still solved; when every one fails, throws a CalibrationError naming each
// model and why it failed.
ModelCalibrations CalibrateStereoAllModels(const StereoData& data,
                                           const CalibrationOptions& options,
                                           const std::vector<ModelKind>& kinds);

// The residuals a known camera and known board poses give on the views
// (e.g. the RMS of the true model on synthetic data): every corner of every
// view with a pose.
std::vector<CornerResidual> Reproject(const CameraModel& model, const CameraData& data,
                                      const std::vector<Pose>& board_poses);

}  // namespace ws::calib
