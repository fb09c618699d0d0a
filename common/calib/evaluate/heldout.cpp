#include "calib/evaluate/heldout.h"

#include <cmath>
#include <algorithm>
#include <iterator>
#include <limits>
#include <numeric>

#include <Eigen/Dense>
#include <map>
#include <optional>
#include <tuple>
#include <utility>

#include "calib/solver/covariance.h"
#include "calib/start/pose_fit.h"

namespace ws::calib {

CameraBlock FixedBlock(const CameraModel& model) {
  CameraBlock block(MakeModel(model.distortion, Coefficients::kIdentifiable));
  block.intrinsics = model.Intrinsics();
  block.coeffs = std::visit([&](const auto& m) { return m.EstimatedCoeffs(model.distortion.coeffs); },
                            block.model);
  block.field = NonRadialField::FromData(model.nonradial);
  const std::vector<double> nonradial = block.field.Coeffs(model.nonradial);
  block.coeffs.insert(block.coeffs.end(), nonradial.begin(), nonradial.end());
  block.fixed = true;
  return block;
}

HeldOutFit FitHeldOutViews(const CameraModel& model, const CameraData& data, int min_points,
                           const BoardWarp& warp) {
  const CameraBlock camera = FixedBlock(model);
  HeldOutFit fit;
  fit.view_rms.assign(data.views.size(), -1.0);
  double sum = 0;
  for (size_t v = 0; v < data.views.size(); ++v) {
    const BoardView& view = data.views[v];
    if (view.size() < min_points) continue;
    const std::vector<char> all(view.size(), 1);
    double best = std::numeric_limits<double>::infinity();
    for (Pose pose : PlanarPoseCandidates(camera, view, all))
      best = std::min(best, RefinePose(camera, view, all, &pose, warp));
    if (!std::isfinite(best)) continue;
    fit.view_rms[v] = best;
    sum += best * best * view.size();
    fit.points += view.size();
    ++fit.views;
  }
  fit.rms_px = fit.points > 0 ? std::sqrt(sum / fit.points) : 0.0;
  return fit;
}

namespace {

// What one board pose's corners (those of every observation on it) add to
// the normal equations of the free parameters f and the pose p, and their
// Schur complement with the pose eliminated: S = A_ff - A_fp A_pp^-1 A_pf,
// b = g_f - A_fp A_pp^-1 g_p; over the free parameters its corners depend
// on (`columns`, ascending: a view reads few of a field's coefficients).
struct PoseTerms {
  int view = -1;
  std::vector<int> blocks;  // into Linearisation::blocks
  // A_pp^-1; none where A_pp is not positive definite (its corners cannot
  // fix the pose: it adds nothing)
  std::optional<Eigen::Matrix<double, 6, 6>> App_inverse;
  std::vector<int> columns;
  Eigen::MatrixXd S;  // columns x columns
  Eigen::VectorXd b;  // columns
};

// *S += sign pose.S and *b += sign pose.b, scattered to the free parameters.
void AddPose(const PoseTerms& pose, double sign, Eigen::MatrixXd* S, Eigen::VectorXd* b) {
  for (size_t i = 0; i < pose.columns.size(); ++i) {
    (*b)(pose.columns[i]) += sign * pose.b(Eigen::Index(i));
    for (size_t j = 0; j < pose.columns.size(); ++j)
      (*S)(pose.columns[i], pose.columns[j]) += sign * pose.S(Eigen::Index(i), Eigen::Index(j));
  }
}

std::vector<PoseTerms> PosesOf(const Problem& problem, const Linearisation& lin) {
  std::vector<PoseTerms> poses;
  for (size_t k = 0; k < lin.blocks.size(); ++k) {
    const Linearisation::Block& block = lin.blocks[k];
    if (block.pose >= int(poses.size())) poses.resize(block.pose + 1);
    PoseTerms& pose = poses[block.pose];
    pose.blocks.push_back(int(k));
    pose.view = problem.observations[block.observation].view;
    std::vector<int> both;
    std::set_union(pose.columns.begin(), pose.columns.end(), block.columns.begin(), block.columns.end(),
                   std::back_inserter(both));
    pose.columns = std::move(both);
  }
  for (PoseTerms& pose : poses) {
    const Eigen::Index n = Eigen::Index(pose.columns.size());
    Eigen::Matrix<double, 6, 6> App = Eigen::Matrix<double, 6, 6>::Zero();
    Eigen::MatrixXd Afp = Eigen::MatrixXd::Zero(n, 6);
    Eigen::Matrix<double, 6, 1> gp = Eigen::Matrix<double, 6, 1>::Zero();
    pose.S = Eigen::MatrixXd::Zero(n, n);
    pose.b = Eigen::VectorXd::Zero(n);
    for (int k : pose.blocks) {
      const Linearisation::Block& block = lin.blocks[k];
      App += block.J_pose.transpose() * block.J_pose;
      gp += block.J_pose.transpose() * block.r;
      const Eigen::MatrixXd& J = block.J_free;
      const Eigen::MatrixXd JtJ = J.transpose() * J, JtP = J.transpose() * block.J_pose;
      const Eigen::VectorXd Jtr = J.transpose() * block.r;
      std::vector<Eigen::Index> at;  // the block's columns among the pose's
      for (int c : block.columns)
        at.push_back(std::lower_bound(pose.columns.begin(), pose.columns.end(), c) - pose.columns.begin());
      for (size_t i = 0; i < at.size(); ++i) {
        Afp.row(at[i]) += JtP.row(Eigen::Index(i));
        pose.b(at[i]) += Jtr(Eigen::Index(i));
        for (size_t j = 0; j < at.size(); ++j) pose.S(at[i], at[j]) += JtJ(Eigen::Index(i), Eigen::Index(j));
      }
    }
    pose.App_inverse = PoseBlockInverse(App);
    if (!pose.App_inverse) continue;
    pose.S.noalias() -= Afp * *pose.App_inverse * Afp.transpose();
    pose.b.noalias() -= Afp * *pose.App_inverse * gp;
  }
  return poses;
}

// The Gauss-Newton step of the free parameters for normal equations S, b
// (S d = -b), S scaled to unit diagonal first (the parameters' units differ
// by orders of magnitude). Directions the fold's views do not determine
// (eigenvalues below 1e-12 of the largest: a spline's spans no training
// corner reaches, without the prior) keep their value, as Levenberg-
// Marquardt from the full solution would; none if S is not finite.
//
// Where every eigenvalue is far above that floor (the Cholesky factor's
// reciprocal condition estimate, within a factor of the size of the true
// one, above 1e-7), none is dropped and the step is the Cholesky solve's,
// in a tenth of the time of the eigenvalues (a camera with a field has
// hundreds of parameters, and each fold of each candidate needs a step).
std::optional<Eigen::VectorXd> Step(const Eigen::MatrixXd& S, const Eigen::VectorXd& b) {
  if (!S.allFinite() || !b.allFinite()) return std::nullopt;
  const Eigen::VectorXd d = S.diagonal().cwiseMax(1e-300).cwiseSqrt().cwiseInverse();
  const Eigen::MatrixXd scaled = d.asDiagonal() * S * d.asDiagonal();
  const Eigen::LLT<Eigen::MatrixXd> llt(scaled);
  if (llt.info() == Eigen::Success && llt.rcond() > 1e-7) {
    Eigen::VectorXd step = -(d.asDiagonal() * llt.solve(d.asDiagonal() * b));
    if (!step.allFinite()) return std::nullopt;
    return step;
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(scaled);
  const Eigen::VectorXd& values = eig.eigenvalues();
  const double floor = 1e-12 * values.cwiseAbs().maxCoeff();
  const Eigen::VectorXd inverse =
      values.unaryExpr([&](double v) { return v > floor ? 1.0 / v : 0.0; });
  const Eigen::MatrixXd& V = eig.eigenvectors();
  Eigen::VectorXd step = -(d.asDiagonal() * (V * (inverse.asDiagonal() * (V.transpose() * (d.asDiagonal() * b)))));
  if (!step.allFinite()) return std::nullopt;
  return step;
}

}  // namespace

CrossValidation CrossValidate(const Problem& solved, int folds) {
  std::vector<int> views;
  for (const Observation& o : solved.observations) views.push_back(o.view);
  std::sort(views.begin(), views.end());
  views.erase(std::unique(views.begin(), views.end()), views.end());
  CrossValidation cv;
  const int n_cameras = int(solved.cameras.size());
  // Fewer views than two a fold: as many folds as there are pairs of views.
  folds = std::min(folds, int(views.size()) / 2);
  if (folds < 2) return cv;
  Problem problem = solved;
  const Linearisation lin = Linearise(problem, "cross-validation");
  const std::vector<PoseTerms> poses = PosesOf(problem, lin);
  Eigen::MatrixXd S_all = lin.prior_J.transpose() * lin.prior_J;
  Eigen::VectorXd b_all = lin.prior_J.transpose() * lin.prior_r;
  for (const PoseTerms& pose : poses)
    if (pose.App_inverse) AddPose(pose, 1, &S_all, &b_all);
  // Each residual pair's corner's distance from its camera's principal point.
  std::vector<std::vector<double>> radius(lin.blocks.size());
  for (size_t b = 0; b < lin.blocks.size(); ++b) {
    const Observation& o = problem.observations[lin.blocks[b].observation];
    for (int i : lin.blocks[b].corners) radius[b].push_back(PixelRadius(problem.cameras[o.camera], o.corners->image[i]));
  }
  std::vector<double> sum(n_cameras, 0.0);
  std::vector<int> count(n_cameras, 0);
  cv.fold_rms_px.assign(n_cameras, {});
  cv.extrapolated.assign(n_cameras, 0);
  for (int k = 0; k < folds; ++k) {
    std::vector<int> held;  // dealt round-robin in view order
    for (size_t i = k; i < views.size(); i += folds) held.push_back(views[i]);
    auto is_held = [&](const PoseTerms& pose) {
      return std::binary_search(held.begin(), held.end(), pose.view);
    };
    // Training: the step from the full solution without the fold's poses.
    Eigen::MatrixXd S = S_all;
    Eigen::VectorXd b = b_all;
    for (const PoseTerms& pose : poses)
      if (pose.App_inverse && is_held(pose)) AddPose(pose, -1, &S, &b);
    const std::optional<Eigen::VectorXd> step = Step(S, b);
    if (!step) continue;  // the other folds do not determine the camera
    // How far from the centre the training views reach, per camera.
    std::vector<double> field(n_cameras, 0.0);
    for (const PoseTerms& pose : poses)
      if (!is_held(pose))
        for (int index : pose.blocks) {
          const int camera = problem.observations[lin.blocks[index].observation].camera;
          for (double r : radius[index]) field[camera] = std::max(field[camera], r);
        }
    // Testing: each held-out pose refitted to its corners under the step.
    std::vector<double> fold_sum(n_cameras, 0.0);
    std::vector<int> fold_count(n_cameras, 0);
    for (const PoseTerms& pose : poses) {
      if (!pose.App_inverse || !is_held(pose)) continue;
      std::vector<Eigen::VectorXd> e;
      Eigen::Matrix<double, 6, 1> gp = Eigen::Matrix<double, 6, 1>::Zero();
      for (int index : pose.blocks) {
        const Linearisation::Block& block = lin.blocks[index];
        Eigen::VectorXd block_step(block.columns.size());
        for (size_t j = 0; j < block.columns.size(); ++j) block_step(Eigen::Index(j)) = (*step)(block.columns[j]);
        e.push_back(block.r + block.J_free * block_step);
        gp += block.J_pose.transpose() * e.back();
      }
      const Eigen::Matrix<double, 6, 1> pose_step = -*pose.App_inverse * gp;
      for (size_t i = 0; i < pose.blocks.size(); ++i) {
        const Linearisation::Block& block = lin.blocks[pose.blocks[i]];
        const int camera = problem.observations[block.observation].camera;
        const Eigen::VectorXd held_out = e[i] + block.J_pose * pose_step;
        for (int j = 0; j < held_out.size() / 2; ++j) {
          if (radius[pose.blocks[i]][j] > field[camera]) {
            ++cv.extrapolated[camera];
            continue;
          }
          const double squared = held_out.segment<2>(2 * j).squaredNorm();
          fold_sum[camera] += squared;
          ++fold_count[camera];
          cv.corners.push_back({camera, pose.view, block.corners[size_t(j)], k, squared});
        }
      }
    }
    for (int c = 0; c < n_cameras; ++c) {
      sum[c] += fold_sum[c];
      count[c] += fold_count[c];
      cv.fold_rms_px[c].push_back(fold_count[c] ? std::sqrt(fold_sum[c] / fold_count[c]) : 0.0);
    }
    ++cv.folds;
  }
  for (int c = 0; c < n_cameras; ++c)
    cv.rms_px.push_back(count[c] ? std::sqrt(sum[c] / count[c]) : -1.0);
  if (cv.folds < 2) cv = CrossValidation{};
  return cv;
}

std::vector<std::vector<double>> FoldRmsOnCommonCorners(
    const std::vector<const std::vector<HeldOutCorner>*>& candidates, int camera, int* corners) {
  using Key = std::tuple<int, int>;  // view, corner
  struct Seen {
    int count = 0, fold = 0;
  };
  std::map<Key, Seen> seen;
  for (size_t c = 0; c < candidates.size(); ++c)
    for (const HeldOutCorner& h : *candidates[c]) {
      if (h.camera != camera) continue;
      Seen& s = seen[{h.view, h.index}];
      if (c == 0) s.fold = h.fold;
      ++s.count;  // a corner is held out once per cross-validation
    }
  int folds = 0, common = 0;
  for (const auto& [key, s] : seen) {
    folds = std::max(folds, s.fold + 1);
    common += s.count == int(candidates.size());
  }
  if (corners) *corners = common;
  std::vector<std::vector<double>> out;
  for (const auto* corners : candidates) {
    std::vector<double> sum(folds, 0.0);
    std::vector<int> count(folds, 0);
    for (const HeldOutCorner& h : *corners) {
      if (h.camera != camera) continue;
      const Seen& s = seen.at({h.view, h.index});
      if (s.count != int(candidates.size())) continue;
      sum[s.fold] += h.squared;
      ++count[s.fold];
    }
    std::vector<double> rms(folds);
    for (int k = 0; k < folds; ++k) rms[k] = count[k] ? std::sqrt(sum[k] / count[k]) : 0.0;
    out.push_back(rms);
  }
  return out;
}

Candidate Scored(std::string name, int parameters, const CrossValidation& cv, int camera) {
  Candidate c;
  c.name = std::move(name);
  c.parameters = parameters;
  if (cv.folds < 2 || size_t(camera) >= cv.rms_px.size() || !std::isfinite(cv.rms_px[camera]) ||
      cv.rms_px[camera] < 0) {
    c.failed = "too few views to hold any out";
    return c;
  }
  c.heldout_rms_px = cv.rms_px[camera];
  c.fold_rms_px = cv.fold_rms_px[camera];
  c.corners = int(std::count_if(cv.corners.begin(), cv.corners.end(),
                                [&](const HeldOutCorner& h) { return h.camera == camera; }));
  return c;
}

}  // namespace ws::calib
