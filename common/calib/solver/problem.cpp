#include "calib/solver/problem.h"

#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <numeric>
#include <set>

#include "calib/solver/covariance.h"
#include "calib/solver/field_blocks.h"
#include "calib/solver/nonradial_prior.h"
#include "calib/solver/residuals.h"
#include "calib/solver/smoothness_prior.h"
#include "runtime/stop_request.h"

namespace ws::calib {
namespace {

ceres::LossFunction* MakeLoss(const SolveSettings& settings) {
  switch (settings.robust_loss) {
    case RobustLoss::kHuber:
      return new ceres::HuberLoss(settings.robust_scale_px);
    case RobustLoss::kCauchy:
      return new ceres::CauchyLoss(settings.robust_scale_px);
    case RobustLoss::kNone:
      break;
  }
  return nullptr;
}

// The parameter blocks of a camera's coefficients (residuals.h): the radial
// model's, the field's segments (field_blocks.h), the tilt's; in the
// coefficients' order, so that the free blocks list the camera's
// parameters as ParamNames does. Pointers into camera.coeffs.
std::vector<std::pair<double*, int>> CoeffBlocks(CameraBlock& camera) {
  const int n = NumRadialCoeffs(camera);
  double* c = camera.coeffs.data();
  std::vector<std::pair<double*, int>> blocks = {{c, n}};
  const FieldBlocks field(camera.field);
  for (int s = 0; s < field.count(); ++s) blocks.emplace_back(c + n + field.Offset(s), field.Size(s));
  if (camera.field.tilt()) blocks.emplace_back(c + n + camera.field.GridCoeffs(), 2);
  return blocks;
}

// Every parameter block of a solve copied into one buffer in a fixed order
// (cameras, extrinsic, poses in the order of the observations). Ceres orders
// blocks by their address in places (the Schur elimination groups), so
// blocks scattered over the heap would make the summation order, and the
// last bits of the solution, differ from run to run.
class ParameterArena {
 public:
  explicit ParameterArena(Problem& problem) {
    auto add = [&](double* block, int size) {
      if (index_.count(block)) return;
      index_[block] = values_.size();
      blocks_.emplace_back(block, size);
      values_.insert(values_.end(), block, block + size);
    };
    for (CameraBlock& camera : problem.cameras) {
      add(camera.intrinsics.data(), kNumIntrinsics);
      for (const auto& [block, size] : CoeffBlocks(camera)) add(block, size);
    }
    add(problem.extrinsic.data.data(), 6);
    add(problem.warp.data.data(), 2);
    for (Observation& o : problem.observations) add(o.pose->data.data(), 6);
  }
  double* operator[](double* block) { return values_.data() + index_.at(block); }
  // The solved values back into the problem's own blocks.
  void CopyBack() const {
    for (const auto& [block, size] : blocks_)
      std::copy_n(values_.data() + index_.at(block), size, block);
  }

 private:
  std::vector<double> values_;
  std::map<double*, size_t> index_;
  std::vector<std::pair<double*, int>> blocks_;
};

constexpr int kExtrinsic = -1, kWarp = -2;  // Built::owner of the rig's blocks

// The Ceres problem of a Problem, and which of its blocks are what (arena
// pointers).
struct Built {
  explicit Built(Problem& problem) : arena(problem) {}
  ParameterArena arena;
  ceres::Problem ceres;
  std::vector<ceres::ResidualBlockId> data_blocks;  // reprojection residuals (not the prior)
  std::vector<int> data_observation;  // per data block: its index in problem.observations
  std::vector<std::vector<int>> data_corners;  // per data block: its observation's corners (ObservationCost)
  int data_residuals = 0;
  std::vector<double*> poses;        // board poses
  std::vector<double*> free_blocks;  // free camera blocks, the extrinsic, the warp
  std::vector<int> owner;  // per free block: its camera, kExtrinsic or kWarp
  std::vector<std::vector<int>> held;  // per free block: entries a manifold holds constant
};

// The inlier corners of an observation as cost functions, each with the
// field's segments its corners read (FieldSupport): one per set of corners
// that read the same segments (one for the view without a field); with a
// robust loss one per corner (Ceres applies a loss per block). A view's
// block in Ceres's Schur complement adds the outer product of every pair of
// its blocks, dense: one block per support adds only the segments' pairs
// that share a corner (on a 16 x 10 field, about a tenth of the view's).
struct ObservationCost {
  std::unique_ptr<ceres::CostFunction> cost;
  std::vector<int> segments;
  std::vector<int> corners;  // the observation's corners it holds, ascending
};
std::vector<ObservationCost> ObservationCosts(const Problem& problem, const Observation& o, bool per_corner) {
  const CameraBlock& camera = problem.cameras[o.camera];
  const double* intrinsics = camera.intrinsics.data();
  struct Group {
    ViewPoints points;
    std::vector<int> corners;
  };
  std::map<std::vector<int>, Group> groups;  // by support; ordered, so the same order every run
  std::vector<std::pair<std::vector<int>, Group>> corners;  // per_corner: in corner order
  for (int i = 0; i < o.corners->size(); ++i) {
    if (!(*o.inliers)[i]) continue;
    const Eigen::Vector2d& x = o.corners->image[i];
    std::vector<int> support = FieldSupport(camera.field, intrinsics, {x.x(), x.y()});
    Group* group = per_corner ? &corners.emplace_back(std::move(support), Group{}).second : &groups[std::move(support)];
    group->points.Add(o.corners->object[i], x, WarpBasis(problem.warp.extent, o.corners->object[i]));
    group->corners.push_back(i);
  }
  for (auto& group : groups) corners.emplace_back(group.first, std::move(group.second));
  std::vector<ObservationCost> costs;
  for (auto& [segments, group] : corners) {
    group.points.max_radius = camera.max_radius;
    costs.push_back({std::unique_ptr<ceres::CostFunction>(MakeCost(camera.model, camera.field,
                                                                   std::move(group.points), o.via_extrinsic, segments)),
                     segments, std::move(group.corners)});
  }
  return costs;
}

// Fills `built` from the problem, a view's corners in blocks by the field's
// segments they read (ObservationCosts); observations that cannot be
// evaluated at the current parameters move to problem.left_out.
void Build(Problem& problem, const SolveSettings& settings, Built* built) {
  const bool per_corner = settings.robust_loss != RobustLoss::kNone;
  std::vector<Observation> kept;
  ParameterArena& arena = built->arena;
  for (Observation& o : problem.observations) {
    CameraBlock& camera = problem.cameras[o.camera];
    std::vector<double*> rig{arena[camera.intrinsics.data()], arena[camera.coeffs.data()],
                             arena[problem.warp.data.data()], arena[o.pose->data.data()]};
    if (o.via_extrinsic) rig.push_back(arena[problem.extrinsic.data.data()]);
    const std::vector<std::pair<double*, int>> coeff_blocks = CoeffBlocks(camera);
    if (camera.field.tilt()) rig.push_back(arena[coeff_blocks.back().first]);
    auto costs = ObservationCosts(problem, o, per_corner);
    std::vector<std::vector<double*>> blocks;  // per cost: the rig's, then its segments
    bool valid = true;
    for (const ObservationCost& c : costs) {
      blocks.push_back(rig);
      for (int segment : c.segments) blocks.back().push_back(arena[coeff_blocks[size_t(1 + segment)].first]);
      std::vector<double> residuals(c.cost->num_residuals());
      valid = valid && c.cost->Evaluate(blocks.back().data(), residuals.data(), nullptr);
    }
    if (!valid) {
      problem.left_out.emplace_back(o.camera, o.view);
      continue;
    }
    kept.push_back(o);
    for (size_t k = 0; k < costs.size(); ++k) {
      built->data_residuals += costs[k].cost->num_residuals();
      built->data_blocks.push_back(
          built->ceres.AddResidualBlock(costs[k].cost.release(), MakeLoss(settings), blocks[k]));
      built->data_observation.push_back(int(kept.size()) - 1);
      built->data_corners.push_back(std::move(costs[k].corners));
    }
    double* pose = arena[o.pose->data.data()];
    if (!costs.empty() &&
        std::find(built->poses.begin(), built->poses.end(), pose) == built->poses.end())
      built->poses.push_back(pose);
  }
  problem.observations = kept;
  if (built->poses.empty()) throw CalibrationError(settings.what + ": no corners to solve with");

  ceres::Problem& cp = built->ceres;
  for (size_t c = 0; c < problem.cameras.size(); ++c) {
    CameraBlock& camera = problem.cameras[c];
    double* intrinsics = arena[camera.intrinsics.data()];
    if (!cp.HasParameterBlock(intrinsics)) continue;
    // The coefficient blocks: the radial one first, then the field's
    // segments and the tilt (a segment no view reads is in the problem
    // only through the field's prior).
    std::vector<double*> coeffs;
    for (const auto& [block, size] : CoeffBlocks(camera)) coeffs.push_back(arena[block]);
    double* radial = coeffs.front();
    const std::vector<double*> all_field(coeffs.begin() + 1, coeffs.end());
    auto in_problem = [&](const std::vector<double*>& blocks) {
      std::vector<double*> out;
      for (double* block : blocks)
        if (cp.HasParameterBlock(block)) out.push_back(block);
      return out;
    };
    auto hold = [&](const std::vector<double*>& blocks) {
      for (double* block : in_problem(blocks)) cp.SetParameterBlockConstant(block);
    };
    if (camera.fixed) {
      cp.SetParameterBlockConstant(intrinsics);
      hold(coeffs);
    } else if (camera.pinhole_only) {
      hold(coeffs);
      cp.SetManifold(intrinsics, new ceres::SubsetManifold(kNumIntrinsics, {kP1, kP2}));
    } else {
      std::vector<int> held_intrinsics, held_coeffs;
      if (!Traits(KindOf(camera.model)).tangential) {  // kb4: p1 = p2 = 0 by definition
        held_intrinsics = {kP1, kP2};
        cp.SetManifold(intrinsics, new ceres::SubsetManifold(kNumIntrinsics, held_intrinsics));
      }
      const int n = NumRadialCoeffs(camera);
      AddSmoothnessPrior(cp, camera.model, radial, n, camera.prior_weight);
      AddNonRadialPrior(cp, camera, all_field);
      const std::vector<double*> field = in_problem(all_field);
      if (camera.free_coeffs == 0) {
        cp.SetParameterBlockConstant(radial);
      } else if (camera.free_coeffs > 0 && camera.free_coeffs < n) {
        for (int k = camera.free_coeffs; k < n; ++k) held_coeffs.push_back(k);
        cp.SetManifold(radial, new ceres::SubsetManifold(n, held_coeffs));
      }
      built->free_blocks.push_back(intrinsics);
      built->held.push_back(held_intrinsics);
      built->free_blocks.push_back(radial);
      built->held.push_back(held_coeffs);
      if (camera.free_coeffs >= 0) {
        hold(field);  // only the radial model's first coefficients free
      } else {
        for (double* block : field) {
          built->free_blocks.push_back(block);
          built->held.emplace_back();
        }
      }
      built->owner.resize(built->free_blocks.size(), int(c));
    }
  }
  double* extrinsic = arena[problem.extrinsic.data.data()];
  if (problem.extrinsic_used && cp.HasParameterBlock(extrinsic)) {
    if (problem.extrinsic_fixed) {
      cp.SetParameterBlockConstant(extrinsic);
    } else {
      built->free_blocks.push_back(extrinsic);
      built->owner.push_back(kExtrinsic);
      built->held.emplace_back();
    }
  }
  double* warp = arena[problem.warp.data.data()];
  if (problem.warp.free) {
    built->free_blocks.push_back(warp);
    built->owner.push_back(kWarp);
    built->held.emplace_back();
  } else if (cp.HasParameterBlock(warp)) {
    cp.SetParameterBlockConstant(warp);
  }
}

bool SolutionValid(const Problem& problem) {
  for (const CameraBlock& camera : problem.cameras)
    if (!AllFinite(camera)) return false;
  if (!problem.extrinsic.AllFinite()) return false;
  for (const Observation& o : problem.observations)
    if (!o.pose->AllFinite()) return false;
  return true;
}

// Ends a solve after the iteration during which a stop was requested.
struct AbortOnStop : ceres::IterationCallback {
  ceres::CallbackReturnType operator()(const ceres::IterationSummary&) override {
    return StopRequested() ? ceres::SOLVER_ABORT : ceres::SOLVER_CONTINUE;
  }
};

}  // namespace

Pose BoardPose(const Problem& problem, const Observation& o) {
  if (!o.via_extrinsic) return *o.pose;
  const Pose& e = problem.extrinsic;
  return Pose::FromRt(e.R() * o.pose->R(), e.R() * o.pose->t() + e.t());
}

SolveOutcome Solve(Problem& problem, const SolveSettings& settings) {
  ThrowIfStopRequested();
  Built built(problem);
  Build(problem, settings, &built);
  ceres::Solver::Options options;
  if (built.free_blocks.empty() && built.poses.size() == 1) {
    options.linear_solver_type = ceres::DENSE_QR;  // one pose: nothing to eliminate
  } else {
    // Schur elimination of the board poses (Ceres's bundle-adjustment layout).
    auto ordering = std::make_shared<ceres::ParameterBlockOrdering>();
    for (double* pose : built.poses) ordering->AddElementToGroup(pose, 0);
    std::vector<double*> all;
    built.ceres.GetParameterBlocks(&all);
    for (double* block : all)
      if (!ordering->IsMember(block)) ordering->AddElementToGroup(block, 1);
    options.linear_solver_type = ceres::DENSE_SCHUR;
    options.linear_solver_ordering = ordering;
  }
  options.num_threads = 1;  // the same input gives the same output
  options.max_num_iterations = settings.max_iterations;
  options.function_tolerance = settings.tolerance;
  options.gradient_tolerance = 1e-2 * settings.tolerance;
  options.parameter_tolerance = settings.tolerance;
  options.logging_type = ceres::SILENT;
  AbortOnStop abort_on_stop;
  options.callbacks.push_back(&abort_on_stop);
  ceres::Solver::Summary summary;
  ceres::Solve(options, &built.ceres, &summary);
  ThrowIfStopRequested();  // a solve cut short is no solution
  built.arena.CopyBack();
  SolveOutcome outcome;
  outcome.message = summary.BriefReport();
  if (!summary.IsSolutionUsable() || !std::isfinite(summary.final_cost) || !SolutionValid(problem))
    throw CalibrationError(settings.what + ": the solver did not reach a valid camera (" +
                           outcome.message + "); the views may not constrain the model");
  return outcome;
}

void EstimateStddev(Problem& problem, const SolveSettings& settings, SolveOutcome* outcome) {
  ThrowIfStopRequested();
  Built built(problem);
  Build(problem, settings, &built);
  if (built.free_blocks.empty()) return;
  // sigma^2 from the data residuals only (the prior is not a measurement).
  ceres::Problem::EvaluateOptions evaluate;
  evaluate.num_threads = 1;
  evaluate.apply_loss_function = false;
  evaluate.residual_blocks = built.data_blocks;
  double cost = 0;
  built.ceres.Evaluate(evaluate, &cost, nullptr, nullptr, nullptr);
  int free_parameters = 6 * static_cast<int>(built.poses.size());
  for (double* block : built.free_blocks)
    free_parameters += built.ceres.ParameterBlockTangentSize(block);
  const int dof = built.data_residuals - free_parameters;
  if (dof <= 0) return;
  const auto covariance =
      CameraCovariance(built.ceres, built.free_blocks, built.poses, 2 * cost / dof);
  if (!covariance) return;
  int offset = 0;
  std::vector<int> camera_index[2];  // per camera parameter: its row of *covariance, or -1
  for (size_t b = 0; b < built.free_blocks.size(); ++b) {
    const int size = built.ceres.ParameterBlockSize(built.free_blocks[b]);
    const std::vector<int>& held = built.held[b];
    const int owner = built.owner[b];
    std::vector<double>& out = owner == kExtrinsic ? outcome->stddev_extrinsic
                               : owner == kWarp    ? outcome->stddev_warp
                                                   : outcome->stddev_camera[owner];
    for (int k = 0; k < size; ++k) {  // a held entry is exact: sigma 0
      const bool exact = std::find(held.begin(), held.end(), k) != held.end();
      out.push_back(exact ? 0.0 : std::sqrt(std::max(0.0, (*covariance)(offset, offset))));
      if (owner >= 0) camera_index[owner].push_back(exact ? -1 : offset);
      offset += !exact;
    }
  }
  for (int c = 0; c < 2; ++c) {
    const std::vector<int>& index = camera_index[c];
    Eigen::MatrixXd& out = outcome->covariance_camera[c];
    out.setZero(index.size(), index.size());
    for (size_t i = 0; i < index.size(); ++i)
      for (size_t j = 0; j < index.size(); ++j)
        if (index[i] >= 0 && index[j] >= 0) out(i, j) = (*covariance)(index[i], index[j]);
  }
}

// Evaluated block by block, as Ceres evaluates (the same cost functions,
// every value finite), without its CRS matrix of the whole problem: building
// and copying that took twice the evaluation itself, in each fold of each
// candidate's cross-validation.
Linearisation Linearise(Problem& problem, const std::string& what) {
  Built built(problem);
  Build(problem, SolveSettings{what}, &built);
  ceres::Problem& cp = built.ceres;
  Linearisation out;
  // Each free block's column per entry, in their order (-1: an entry its
  // manifold holds); a constant one has its columns and no entries, as in
  // Ceres's Jacobian.
  std::map<const double*, std::vector<int>> free_columns;
  for (size_t f = 0; f < built.free_blocks.size(); ++f) {
    double* block = built.free_blocks[f];
    const std::vector<int>& held = built.held[f];
    std::vector<int> columns(size_t(cp.ParameterBlockSize(block)), -1);
    for (size_t e = 0; e < columns.size(); ++e)
      if (std::find(held.begin(), held.end(), int(e)) == held.end()) columns[e] = out.free_size++;
    free_columns[block] = cp.IsParameterBlockConstant(block) ? std::vector<int>{} : std::move(columns);
  }
  // A residual block's residuals and Jacobian: by the free parameters over
  // *columns (with `columns`, those it depends on, ascending; else every
  // one) and by `pose` (if not null) into *J_pose.
  auto evaluate = [&](ceres::ResidualBlockId id, const double* pose, Eigen::VectorXd* r,
                      std::vector<int>* columns, Eigen::MatrixXd* J_free, Eigen::MatrixXd* J_pose) {
    std::vector<double*> blocks;
    cp.GetParameterBlocksForResidualBlock(id, &blocks);
    const ceres::CostFunction* cost = cp.GetCostFunctionForResidualBlock(id);
    const int m = cost->num_residuals();
    std::vector<std::vector<double>> jacobians(blocks.size());
    std::vector<double*> wanted(blocks.size(), nullptr);
    std::vector<int> at(size_t(out.free_size), -1);  // free column -> column of *J_free
    for (size_t j = 0; j < blocks.size(); ++j) {
      const auto free = free_columns.find(blocks[j]);
      const bool is_free = free != free_columns.end() && !free->second.empty();
      if (blocks[j] != pose && !is_free) continue;
      jacobians[j].resize(size_t(m) * size_t(cost->parameter_block_sizes()[j]));
      wanted[j] = jacobians[j].data();
      if (is_free)
        for (int c : free->second)
          if (c >= 0) at[size_t(c)] = 0;
    }
    if (columns) {
      for (int c = 0; c < out.free_size; ++c)
        if (at[size_t(c)] == 0) {
          at[size_t(c)] = int(columns->size());
          columns->push_back(c);
        }
    } else {
      std::iota(at.begin(), at.end(), 0);
    }
    r->resize(m);
    bool valid = cost->Evaluate(blocks.data(), r->data(), wanted.data()) && r->allFinite();
    J_free->setZero(m, columns ? Eigen::Index(columns->size()) : out.free_size);
    if (J_pose) J_pose->setZero(m, 6);
    for (size_t j = 0; j < blocks.size(); ++j) {
      if (!wanted[j]) continue;
      const int size = cost->parameter_block_sizes()[j];
      const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> J(
          wanted[j], m, size);
      valid = valid && J.allFinite();
      if (blocks[j] == pose) {
        J_pose->leftCols(size) = J;
        continue;
      }
      const std::vector<int>& entry_column = free_columns.at(blocks[j]);
      for (int e = 0; e < size; ++e)
        if (entry_column[size_t(e)] >= 0) J_free->col(at[size_t(entry_column[size_t(e)])]) = J.col(e);
    }
    if (!valid) throw CalibrationError(what + ": the residuals cannot be evaluated at the solution");
  };
  for (size_t b = 0; b < built.data_blocks.size(); ++b) {
    const Observation& o = problem.observations[built.data_observation[b]];
    const double* pose = built.arena[o.pose->data.data()];
    Linearisation::Block block;
    block.observation = built.data_observation[b];
    block.corners = std::move(built.data_corners[b]);
    block.pose = int(std::find(built.poses.begin(), built.poses.end(), pose) - built.poses.begin());
    evaluate(built.data_blocks[b], pose, &block.r, &block.columns, &block.J_free, &block.J_pose);
    out.blocks.push_back(std::move(block));
  }
  // The other residual blocks (the priors), stacked.
  std::vector<ceres::ResidualBlockId> all;
  cp.GetResidualBlocks(&all);
  const std::set<ceres::ResidualBlockId> data(built.data_blocks.begin(), built.data_blocks.end());
  std::vector<Eigen::VectorXd> r;
  std::vector<Eigen::MatrixXd> J;
  Eigen::Index rows = 0;
  for (ceres::ResidualBlockId id : all) {
    if (data.count(id)) continue;
    r.emplace_back();
    J.emplace_back();
    evaluate(id, nullptr, &r.back(), nullptr, &J.back(), nullptr);
    rows += r.back().size();
  }
  out.prior_r.resize(rows);
  out.prior_J.resize(rows, out.free_size);
  for (size_t k = 0, row = 0; k < r.size(); row += size_t(r[k].size()), ++k) {
    out.prior_r.segment(Eigen::Index(row), r[k].size()) = r[k];
    out.prior_J.middleRows(Eigen::Index(row), r[k].size()) = J[k];
  }
  return out;
}

std::vector<CornerResidual> Residuals(const Problem& problem, int camera) {
  std::vector<CornerResidual> out;
  const CameraBlock& block = problem.cameras[camera];
  for (const Observation& o : problem.observations) {
    if (o.camera != camera) continue;
    const Pose pose = BoardPose(problem, o);
    const Eigen::Matrix3d R = pose.R();
    const Eigen::Vector3d t = pose.t();
    for (int i = 0; i < o.corners->size(); ++i) {
      const auto pixel = ProjectPoint(block, R * Warped(problem.warp, o.corners->object[i]) + t);
      CornerResidual r;
      r.view = o.view;
      r.index = i;
      r.id = o.corners->ids[i];
      r.observed = o.corners->image[i];
      r.residual = pixel ? Eigen::Vector2d(*pixel - r.observed) : Eigen::Vector2d(NAN, NAN);
      r.outlier = !(*o.inliers)[i];
      out.push_back(r);
    }
  }
  return out;
}

}  // namespace ws::calib
