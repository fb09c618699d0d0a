#include "calib/stereo_solve.h"

#include <Eigen/Dense>
#include <algorithm>
#include <exception>
#include <opencv2/core/utility.hpp>

#include "calib/camera_result.h"
#include "calib/half_turn.h"
#include "calib/mono_solve.h"
#include "calib/pair_consistency.h"
#include "calib/solver/outliers.h"
#include "calib/solver/stage_log.h"

namespace ws::calib {
namespace {

// The mean of the relative poses right * left^-1 of the stereo views:
// rotation by the chordal mean (SVD of the summed matrices), translation by
// the per-coordinate median.
Pose AverageExtrinsic(const std::vector<Pose>& left, const std::vector<Pose>& right) {
  Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
  std::vector<double> t[3];
  for (size_t j = 0; j < left.size(); ++j) {
    const Eigen::Matrix3d R = right[j].R() * left[j].R().transpose();
    sum += R;
    const Eigen::Vector3d T = right[j].t() - R * left[j].t();
    for (int k = 0; k < 3; ++k) t[k].push_back(T(k));
  }
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(sum, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d U = svd.matrixU();
  if ((U * svd.matrixV().transpose()).determinant() < 0) U.col(2) = -U.col(2);
  Eigen::Vector3d T;
  for (int k = 0; k < 3; ++k) {
    std::sort(t[k].begin(), t[k].end());
    const size_t n = t[k].size();
    T(k) = n % 2 ? t[k][n / 2] : 0.5 * (t[k][n / 2 - 1] + t[k][n / 2]);
  }
  return Pose::FromRt(U * svd.matrixV().transpose(), T);
}

// Each camera's own solve, the two at once on OpenCV's pool (in turn
// where the models run at once). An error is the left camera's when both
// fail, as when they ran one after the other.
void SolveBothMono(const StereoData& data, const BoardExtent& board,
                   const CalibrationOptions& options, const ModelPlan& plan, MonoState mono[2]) {
  std::exception_ptr error[2];
  cv::parallel_for_(
      cv::Range(0, 2),
      [&](const cv::Range& range) {
        for (int c = range.start; c < range.end; ++c) try {
            SolveMono(c == 0 ? data.left : data.right, board, options, plan, &mono[c], c);
          } catch (...) {
            error[c] = std::current_exception();
          }
      },
      2);
  for (const std::exception_ptr& e : error)
    if (e) std::rethrow_exception(e);
}

}  // namespace

StereoCalibration SolveStereo(const StereoData& data, const CalibrationOptions& options,
                              const ModelPlan& plan) {
  if (data.left.views.size() != data.right.views.size())
    throw CalibrationError("the left and right cameras have different numbers of views");
  MonoState mono[2];
  const BoardExtent board = ExtentOf({&data.left, &data.right});
  SolveBothMono(data, board, options, plan, mono);
  const int n = data.size();
  std::vector<bool> is_stereo(n, false);
  for (int v = 0; v < n; ++v)
    is_stereo[v] = mono[0].prepared.usable[v] && mono[1].prepared.usable[v];
  StereoCalibration out;
  out.model = plan.model;
  out.flow = plan.flow;
  out.joint_left_out = options.flow == StereoFlow::kJoint && plan.flow != StereoFlow::kJoint;
  out.half_turned_views = MakeHalfTurnsConsistent(board, is_stereo, mono[0], &mono[1]);
  for (int v : out.half_turned_views)
    Say(options, "view " + std::to_string(v) +
                     ": the right image's corners were numbered half-turned (a symmetric "
                     "board), renumbered to match the left's");
  for (int c = 0; c < 2; ++c)
    (c == 0 ? out.left : out.right) =
        CameraResult(mono[c].problem, 0, mono[c].prepared, mono[c].outcome,
                     mono[c].init_method, options);

  std::vector<Pose> left_poses, right_poses;
  for (int v = 0; v < n; ++v) {
    if (!is_stereo[v]) continue;
    left_poses.push_back(mono[0].poses[v]);
    right_poses.push_back(mono[1].poses[v]);
  }
  out.views = static_cast<int>(left_poses.size());
  if (out.views < options.min_stereo_views)
    throw CalibrationError("only " + std::to_string(out.views) +
                           " views where both cameras see the board, at least " +
                           std::to_string(options.min_stereo_views) +
                           " needed for R and T (hold the board where both cameras see it)");

  Problem problem;
  problem.cameras = {mono[0].problem.cameras[0], mono[1].problem.cameras[0]};
  problem.extrinsic = AverageExtrinsic(left_poses, right_poses);
  problem.extrinsic_used = true;
  // One board: R, T with the mean of the cameras' own estimates of its warp,
  // the joint solve estimating it.
  problem.warp = mono[0].warp;
  for (int k = 0; k < 2; ++k) problem.warp.data[k] = 0.5 * (mono[0].warp.data[k] + mono[1].warp.data[k]);
  const BoardWarp mean_warp = problem.warp;
  std::vector<Pose> poses[2] = {mono[0].poses, mono[1].poses};
  Inliers inliers[2] = {mono[0].inliers, mono[1].inliers};
  // The stereo views (and with all_views every other usable view), the right
  // camera of a stereo view on the left's board pose through R, T.
  auto observe = [&](bool all_views) {
    problem.observations.clear();
    for (int v = 0; v < n; ++v) {
      if (!is_stereo[v] && !all_views) continue;
      for (int c = 0; c < 2; ++c)
        if (mono[c].prepared.usable[v])
          problem.observations.push_back({c, v, &mono[c].prepared.views[v], &inliers[c][v],
                                          is_stereo[v] ? &poses[0][v] : &poses[c][v],
                                          c == 1 && is_stereo[v]});
    }
  };
  // Each camera's outliers are out already, decided on its own fit: the
  // stereo solves keep them out and leave out no more, since a pair whose
  // cameras were not exposed together would otherwise lose its corners to
  // the shared board pose one by one instead of being found (CheckPairs).
  // The standard deviations only of the solve that is kept (below).
  // R, T with both cameras held at their own solutions: the paper's
  // extrinsic step, and the start of the joint solve.
  auto solve_extrinsics = [&] {
    for (int c = 0; c < 2; ++c) {
      problem.cameras[c] = mono[c].problem.cameras[0];
      problem.cameras[c].fixed = true;
      poses[c] = mono[c].poses;
      inliers[c] = mono[c].inliers;
    }
    problem.warp = mean_warp;
    observe(false);
    return SolveWithRejection(problem, OnTheCorners(options, "stereo extrinsics"));
  };
  auto solve_joint = [&] {
    for (auto& camera : problem.cameras) camera.fixed = false;
    problem.warp.free = options.board_warp == WarpRule::kEstimated ||
                        mono[0].warp_choice.kept || mono[1].warp_choice.kept;
    observe(true);
    return SolveWithRejection(problem, OnTheCorners(options, "joint stereo solve"));
  };
  const bool joint = plan.flow == StereoFlow::kJoint;
  // Pairs that no rig explains leave R, T; each camera keeps the view. They
  // are judged on the joint solve where there is one (its cameras take up
  // each camera's own small errors), else with the cameras held; the radial
  // solve's judgement stands where there was one (plan.unpaired).
  SolveOutcome outcome;
  if (!plan.unpaired) {
    outcome = solve_extrinsics();
    if (joint) outcome = solve_joint();
  }
  out.inconsistent_views = plan.unpaired ? *plan.unpaired : CheckPairs(problem, mono, is_stereo).inconsistent;
  if (plan.unpaired || !out.inconsistent_views.empty()) {
    for (int v : out.inconsistent_views) {
      is_stereo[v] = false;
      Say(options, "view " + std::to_string(v) +
                       ": the pair does not fit one rig (unsynchronised or misordered), left out "
                       "of R, T");
    }
    out.views -= static_cast<int>(out.inconsistent_views.size());
    if (out.views < options.min_stereo_views)
      throw CalibrationError("only " + std::to_string(out.views) +
                             " consistent stereo views, at least " +
                             std::to_string(options.min_stereo_views) + " needed for R and T");
    outcome = solve_extrinsics();
    if (joint) outcome = solve_joint();
  }
  // Where some pairs showed that the cameras were not exposed together, the
  // joint solve is kept only if sharing the board poses costs what it should;
  // otherwise each camera keeps its own views' solution (the paper's flow).
  const bool keep_joint =
      joint && (out.inconsistent_views.empty() || JointFitsAsWellAsAlone(problem, mono, out.views));
  if (joint && !keep_joint) {
    outcome = solve_extrinsics();
    out.flow = StereoFlow::kPaper;
    out.joint_left_out = true;
    Say(options, "joint solve left out: sharing the board poses worsens the cameras' fit beyond "
                 "chance (pairs not exposed together?); each camera from its own views");
  }
  if (options.covariance)
    EstimateStddev(problem, StageSettings(options, "stereo standard deviations", options.max_iterations),
                   &outcome);
  if (keep_joint) {
    Say(options, "joint solve: baseline " + Fixed(problem.extrinsic.t().norm(), 5) + " m (" +
                     outcome.message + ")");
    for (int c = 0; c < 2; ++c)
      (c == 0 ? out.left : out.right) =
          CameraResult(problem, c, mono[c].prepared, outcome, mono[c].init_method, options);
  }
  // Held-out RMS: of the joint solve where it is kept, else of each
  // camera's own solve (R, T then play no part in it).
  const CrossValidation joint_cv =
      keep_joint ? CrossValidate(problem, options.cv_folds) : CrossValidation{};
  for (int c = 0; c < 2; ++c) {
    CameraCalibration& camera = c == 0 ? out.left : out.right;
    camera.knot_curve = mono[c].knot_curve;
    camera.warp_choice = mono[c].warp_choice;
    camera.field_curve = mono[c].field_curve;
    camera.field_chosen = mono[c].field_chosen;
    camera.selections = mono[c].selections;
    if (keep_joint)
      SetHeldOut(joint_cv, c, &camera);
    else
      SetHeldOut(HeldOut(mono[c], options), 0, &camera);
  }
  Say(options, "stereo extrinsics from " + std::to_string(out.views) + " views: baseline " +
                   Fixed(problem.extrinsic.t().norm(), 5) + " m");
  out.R = problem.extrinsic.R();
  out.T = problem.extrinsic.t();
  out.extrinsic_names = {"rx", "ry", "rz", "tx", "ty", "tz"};
  out.extrinsic_stddev = outcome.stddev_extrinsic;

  // Stereo quality: both cameras' corners of the stereo views.
  std::vector<CornerResidual> both;
  for (int c = 0; c < 2; ++c)
    for (const auto& r : Residuals(problem, c))
      if (is_stereo[r.view]) both.push_back(r);
  out.rms_px = Rms(both);
  out.view_rms = ViewRms(both, n);
  return out;
}

}  // namespace ws::calib
