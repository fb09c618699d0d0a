// The least-squares problem of paper Eq. 10 over any set of cameras, views
// and poses, and its solution with Ceres.
//
// A Problem holds the cameras (CameraBlock), and one Observation per camera
// per view: which corners (with an inlier mask) and which board pose. A
// right camera's observation of a stereo view can take the left camera's
// board pose through the extrinsic (X_right = R X_left + T). Poses and masks
// live outside the problem, so the stages of a calibration can share them.
#pragma once

#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

#include "calib/solver/board_warp.h"
#include "calib/solver/calib_data.h"
#include "calib/solver/camera_block.h"
#include "calib/solver/pose.h"
#include "calib/solver/quality.h"

namespace ws::calib {

using Inliers = std::vector<std::vector<char>>;  // per view, per corner: 1 = used

struct Observation {
  int camera = 0;
  int view = 0;
  const BoardView* corners = nullptr;
  std::vector<char>* inliers = nullptr;
  Pose* pose = nullptr;  // board -> this camera, or board -> left when via_extrinsic
  bool via_extrinsic = false;
};

struct Problem {
  std::vector<CameraBlock> cameras;
  std::vector<Observation> observations;
  Pose extrinsic;  // left -> right camera
  bool extrinsic_used = false;
  bool extrinsic_fixed = false;
  BoardWarp warp;  // the board's deflection, shared by every observation (held unless free)
  std::vector<std::pair<int, int>> left_out;  // (camera, view) that could not be evaluated
};

struct SolveSettings {
  std::string what;  // for error messages: "left camera (bspline)"
  int max_iterations = 100;
  RobustLoss robust_loss = RobustLoss::kNone;
  double robust_scale_px = 1.0;
  // Ceres's function and parameter tolerance (relative); a solve that only
  // has to rank or cross-validate (heldout.h, --knots auto) stops at
  // kRankingTolerance: 4 digits of an RMS need no more.
  double tolerance = 1e-12;
};
inline constexpr double kRankingTolerance = 1e-7;

struct SolveOutcome {
  std::string message;  // Ceres's brief report
  // Standard deviations of each free camera's intrinsics and coefficients
  // (ParamNames order) and of the extrinsic (rx ry rz tx ty tz); empty when
  // not computed or not determined by the data.
  std::vector<double> stddev_camera[2];
  std::vector<double> stddev_extrinsic;
  std::vector<double> stddev_warp;  // x2, y2 when the warp was free
  // Each camera's full covariance over the same parameters (held entries 0
  // in their row and column); empty when the stddevs are.
  Eigen::MatrixXd covariance_camera[2];
};

// The board -> camera pose of an observation (through the extrinsic for a
// right camera on the left's pose).
Pose BoardPose(const Problem& problem, const Observation& observation);

// Solves the problem over the inlier corners, in place. Observations whose
// corners cannot be projected at the start (behind the camera, past
// max_radius) are removed from it and listed in left_out. Throws
// CalibrationError when nothing is left to solve or the solver does not
// reach a valid camera; throws Stopped (runtime/stop_request.h), the problem
// unchanged, when a stop is requested before or during the solve.
SolveOutcome Solve(Problem& problem, const SolveSettings& settings);

// The standard deviations of the free parameters at the current solution
// (covariance.h), into outcome; throws Stopped as Solve does.
void EstimateStddev(Problem& problem, const SolveSettings& settings, SolveOutcome* outcome);

// The problem linearised at its parameters, without a robust loss: per
// set of an observation's inlier corners that read the same segments of
// the field (all of them without a field), their residuals (u and v) and their
// Jacobian by the free parameters (the free cameras, extrinsic and warp in
// their tangent spaces, as EstimateStddev orders them) and by its board
// pose; the smoothness prior's residuals and Jacobian by the free
// parameters. Observations that cannot be evaluated move to left_out
// (Solve); throws CalibrationError if nothing can.
struct Linearisation {
  struct Block {
    int observation = 0;  // index into problem.observations
    int pose = 0;         // the board pose's index among the distinct poses
    std::vector<int> corners;  // the observation's corners, ascending: rows 2i and 2i + 1 are corners[i]'s
    Eigen::VectorXd r;
    // The free parameters its rows depend on (a view reads few of a
    // field's coefficients), ascending, and d r / d them: J_free's column
    // j is the free parameter columns[j].
    std::vector<int> columns;
    Eigen::MatrixXd J_free, J_pose;  // J_pose: 6 columns
  };
  int free_size = 0;
  std::vector<Block> blocks;
  Eigen::VectorXd prior_r;
  Eigen::MatrixXd prior_J;
};
Linearisation Linearise(Problem& problem, const std::string& what);

// Every corner of camera `camera` with its residual (outliers flagged), the
// board displaced by the problem's warp.
std::vector<CornerResidual> Residuals(const Problem& problem, int camera);

}  // namespace ws::calib
