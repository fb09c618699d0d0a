#include "calib/calibrate.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <map>
#include <memory>
#include <mutex>
#include <numeric>
#include <optional>
#include <opencv2/core/utility.hpp>
#include <stdexcept>

#include "calib/camera_result.h"
#include "calib/evaluate/heldout.h"
#include "calib/mono_solve.h"
#include "calib/solver/stage_log.h"
#include "calib/start/angle_start.h"
#include "calib/stereo_solve.h"
#include "models/model_registry.h"

namespace ws::calib {

void CheckOptions(const CalibrationOptions& options) {
  const SplineOptions& spline = options.spline;
  if (spline.knots && (*spline.knots < 2 || *spline.knots > 64))
    throw CalibrationError("the B-spline needs 2 to 64 knots, not " + std::to_string(*spline.knots));
  if (Traits(options.model).spline && !spline.knots && options.cv_folds < 2)
    throw CalibrationError("--knots auto needs cross-validation (at least 2 folds)");
  if (options.min_views < 3) throw CalibrationError("min_views must be at least 3");
  if (!(spline.smoothness >= 0)) throw CalibrationError("the smoothness weight must be >= 0");
}

std::optional<int> ParseKnots(const std::string& value) {
  if (value == "auto") return std::nullopt;
  size_t used = 0;
  int knots = 0;
  try {
    knots = std::stoi(value, &used);
  } catch (const std::exception&) {  // std::stoi says only "stoi"
  }
  if (used == 0 || used != value.size() || knots < 2 || knots > 64)
    throw std::invalid_argument("knots must be 'auto' or a count from 2 to 64, not '" + value + "'");
  return knots;
}

void ParseFieldRule(const std::string& value, CalibrationOptions* options) {
  options->field_cols = options->field_rows = 0;
  options->field_tilt = false;
  if (value == "auto" || value == "none") {
    options->nonradial = value == "auto" ? FieldRule::kAuto : FieldRule::kNone;
    return;
  }
  options->nonradial = FieldRule::kGrid;
  const std::string tilt = "tilt";
  options->field_tilt = value.rfind(tilt, 0) == 0;
  if (value == tilt) return;
  const std::string grid = options->field_tilt && value.size() > tilt.size() && value[tilt.size()] == '+'
                               ? value.substr(tilt.size() + 1)
                               : value;
  int cols = 0, rows = 0;
  char x = 0, extra = 0;
  if (std::sscanf(grid.c_str(), "%d%c%d%c", &cols, &x, &rows, &extra) != 3 || x != 'x' ||
      cols < 4 || rows < 4 || cols > 64 || rows > 64)
    throw std::invalid_argument("--nonradial must be auto, none, tilt, COLSxROWS or tilt+COLSxROWS "
                                "(4 to 64 each, as 8x6), not '" + value + "'");
  options->field_cols = cols;
  options->field_rows = rows;
}

OutlierRule ParseOutlierRule(const std::string& value, double* sigma) {
  if (value == "auto") return OutlierRule::kChauvenet;
  if (value == "off") return OutlierRule::kOff;
  size_t used = 0;
  double k = -1;
  try {
    k = std::stod(value, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != value.size() || !(k >= 0) || !std::isfinite(k))
    throw std::invalid_argument("--outlier-sigma must be auto, off or a number of sigmas, not '" +
                                value + "'");
  if (k == 0) return OutlierRule::kOff;
  *sigma = k;
  return OutlierRule::kSigma;
}

namespace {

// One camera with the model of `plan`.
CameraCalibration SolveCamera(const CameraData& data, const CalibrationOptions& options,
                              const ModelPlan& plan) {
  MonoState state;
  SolveMono(data, ExtentOf({&data}), options, plan, &state, 0, cv::getNumThreads());
  CameraCalibration result =
      CameraResult(state.problem, 0, state.prepared, state.outcome, state.init_method, options);
  result.knot_curve = state.knot_curve;
  result.warp_choice = state.warp_choice;
  result.field_curve = state.field_curve;
  result.field_chosen = state.field_chosen;
  result.selections = state.selections;
  SetHeldOut(HeldOut(state, options), 0, &result);
  return result;
}

// The rig (or its one camera) with the model of `plan`.
StereoCalibration SolveModel(const StereoData& data, const CalibrationOptions& options,
                             const ModelPlan& plan) {
  const auto start = std::chrono::steady_clock::now();
  // No right image at all (not merely no board in it): a one-camera rig.
  const bool mono = data.right.image_width == 0 &&
                    std::all_of(data.right.views.begin(), data.right.views.end(),
                                [](const BoardView& view) { return view.empty(); });
  StereoCalibration result;
  if (mono) {
    result.model = plan.model;
    result.mono = true;
    result.left = SolveCamera(data.left, options, plan);
    result.rms_px = result.left.rms_px;  // the rig's RMS is its one camera's
  } else {
    result = SolveStereo(data, options, plan);
  }
  result.solve_seconds = Seconds(start);
  return result;
}

}  // namespace

CameraCalibration CalibrateCamera(const CameraData& data, const CalibrationOptions& options) {
  CheckOptions(options);
  return SolveCamera(data, options, PlanAsAsked(options));
}

StereoCalibration CalibrateStereo(const StereoData& data, const CalibrationOptions& options) {
  CheckOptions(options);
  return SolveModel(data, options, PlanAsAsked(options));
}

namespace {

// A camera's noise level from its fit: the RMS per corner over the
// degrees of freedom left, rms sqrt(n / (n - p)) for n coordinates and p
// parameters (its own and its views' poses), the unbiased estimate of
// least squares; infinite where the fit leaves none.
double FittedNoise(const CameraCalibration& camera) {
  const double n = 2.0 * camera.points;
  const double p = double(camera.param_names.size()) + 6.0 * camera.views;
  return n > p ? camera.rms_px * std::sqrt(n / (n - p)) : INFINITY;
}

// Why no pinhole-radius model can image the views: every angle model
// solved (and at least one) puts inlier corners of a camera at 90 degrees or
// more off the axis, where r = tan(theta) has no value; "" otherwise.
std::string BeyondPinhole(const std::vector<ModelKind>& kinds,
                          const std::vector<std::optional<StereoCalibration>>& solved) {
  double least = INFINITY;  // radians: the smallest reach the angle models give
  std::string names;
  for (size_t k = 0; k < kinds.size(); ++k) {
    if (!Traits(kinds[k]).angle || !solved[k]) continue;
    const StereoCalibration& c = *solved[k];
    least = std::min(least, std::max(c.left.max_observed_radius,
                                     c.mono ? 0.0 : c.right.max_observed_radius));
    names += (names.empty() ? "" : " and ") + ModelName(kinds[k]);
  }
  if (!(least >= M_PI / 2) || !std::isfinite(least)) return "";
  return names + " image corners up to at least " + Fixed(least * 180 / M_PI, 0) +
         " degrees off the axis, where a pinhole radius tan(theta) has none";
}

// ModelCalibrations::model_selection: the rule of selection.h over the
// models solved, in order of their parameters per camera, each fold's RMS
// on the held-out corners they all kept (FoldRmsOnCommonCorners: their
// outliers are part of each fit, never a criterion) pooled over the
// cameras. A model that uses fewer views than another is not scored: it
// predicts nothing of the views it cannot use (a pinhole model's past 90
// degrees), so it cannot be scored on the same corners. Where nothing was
// cross-validated (fewer than 4 views), the lowest FittedNoise, the
// cameras pooled. The models that failed are listed with their error.
// *chosen: the index into `solved` of the model chosen.
Selection ChooseModel(const std::vector<StereoCalibration>& solved,
                      const std::vector<ModelFailure>& failed, int* chosen) {
  auto views = [](const StereoCalibration& c) { return c.left.views + (c.mono ? 0 : c.right.views); };
  int most = 0;
  for (const auto& c : solved) most = std::max(most, views(c));
  std::vector<int> order(solved.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return solved[a].left.param_names.size() < solved[b].left.param_names.size();
  });
  const bool cross_validated = std::all_of(solved.begin(), solved.end(), [](const auto& c) {
    return !c.left.heldout_fold_rms_px.empty() && (c.mono || !c.right.heldout_fold_rms_px.empty());
  });
  std::vector<std::vector<double>> folds;
  int corners = 0;
  for (const bool right : {false, true}) {
    if (!cross_validated || (right && solved.front().mono)) break;
    std::vector<const std::vector<HeldOutCorner>*> held;
    for (int i : order) held.push_back(&(right ? solved[i].right : solved[i].left).heldout_corners);
    int common = 0;
    const auto rms = FoldRmsOnCommonCorners(held, 0, &common);
    corners += common;
    if (!right) {
      folds = rms;
      continue;
    }
    for (size_t i = 0; i < folds.size(); ++i)
      for (size_t k = 0; k < folds[i].size() && k < rms[i].size(); ++k)
        folds[i][k] = std::hypot(folds[i][k], rms[i][k]) / std::sqrt(2.0);
  }
  std::vector<Candidate> candidates;
  for (size_t j = 0; j < order.size(); ++j) {
    const StereoCalibration& c = solved[order[j]];
    Candidate candidate;
    candidate.name = ModelName(c.model);
    candidate.parameters = int(c.left.param_names.size());
    if (views(c) < most) {
      candidate.failed = "uses " + std::to_string(views(c)) + " of the " + std::to_string(most) +
                         " views another model uses";
    } else if (!cross_validated) {
      candidate.failed = "too few views to hold any out";
    } else {
      candidate.fold_rms_px = folds[j];
      double sum = 0;
      for (double f : folds[j]) sum += f * f;
      candidate.heldout_rms_px = std::sqrt(sum / double(std::max<size_t>(folds[j].size(), 1)));
      candidate.corners = corners;
    }
    candidates.push_back(candidate);
  }
  for (const ModelFailure& f : failed) candidates.push_back({f.model, 0, -1, {}, 0, f.error});
  Selection selection = Select("", "model", candidates);
  if (!cross_validated && !solved.empty()) {
    auto noise = [](const StereoCalibration& c) {
      return c.mono ? FittedNoise(c.left) : std::hypot(FittedNoise(c.left), FittedNoise(c.right));
    };
    int lowest = -1;
    for (size_t j = 0; j < order.size(); ++j)
      if (views(solved[order[j]]) == most &&
          (lowest < 0 || noise(solved[order[j]]) < noise(solved[order[lowest]])))
        lowest = int(j);
    selection.chosen = selection.best = lowest;
    selection.why = "fewer than 4 views, so none can be held out: the lowest RMS over the "
                    "degrees of freedom left, rms sqrt(n / (n - p)), " +
                    Fixed(noise(solved[order[lowest]])) + " px";
  }
  if (selection.chosen < 0) {  // no held-out corner all of them kept: the simplest
    selection.chosen = 0;
    selection.why += "; the simplest solved is published";
  }
  *chosen = order[size_t(selection.chosen)];  // the failed models follow the solved ones
  return selection;
}

}  // namespace

ModelCalibrations CalibrateStereoAllModels(const StereoData& data,
                                           const CalibrationOptions& options,
                                           const std::vector<ModelKind>& kinds) {
  CheckOptions(options);
  const auto start = std::chrono::steady_clock::now();
  ModelCalibrations results;
  // Several models are compared radially; the chosen one then gets its
  // non-radial field.
  const bool field_after = kinds.size() > 1 && options.nonradial != FieldRule::kNone;
  // The models on every core at once (a model's two cameras then run one
  // after the other: OpenCV runs a nested parallel region in turn), each
  // result in its place; the progress lines serialised. The angle models
  // first: where every one solved images corners 90 degrees or more off
  // the axis, a pinhole-radius model (r = tan theta) has no image of them,
  // so it could not be scored on the corners the others use (ChooseModel),
  // and it is not tried.
  std::vector<std::optional<StereoCalibration>> solved(kinds.size());
  std::vector<std::string> errors(kinds.size());
  std::vector<std::shared_ptr<RadialStates>> radial(kinds.size());  // each model's, for its field
  const auto angle_starts = std::make_shared<AngleStarts>();  // solved once for the angle models
  std::exception_ptr stopped;
  std::mutex done_mutex;
  int done = 0;
  auto solve_one = [&](size_t k) {
    try {
      if (field_after) radial[k] = std::make_shared<RadialStates>();
      solved[k] = SolveModel(data, options,
                             {kinds[k], field_after ? FieldRule::kNone : options.nonradial,
                              options.flow, std::nullopt, radial[k], nullptr, angle_starts});
    } catch (const CalibrationError& e) {
      errors[k] = e.what();
    } catch (...) {  // Stopped: the run ends
      std::lock_guard<std::mutex> lock(done_mutex);
      stopped = std::current_exception();
    }
    std::lock_guard<std::mutex> lock(done_mutex);
    const int finished = ++done;
    Say(options, "models: " + std::to_string(finished) + " of " + std::to_string(kinds.size()) +
                     " solved (" + ModelName(kinds[k]) + "), " + TimeLeft(start, finished, int(kinds.size())) +
                     (field_after ? " before the chosen model's non-radial part" : ""));
  };
  // One model alone runs on this thread, so that its own solve can take
  // every core (OpenCV runs a nested parallel region in turn).
  auto solve = [&](const std::vector<size_t>& which) {
    if (which.size() == 1) {
      solve_one(which[0]);
    } else {
      cv::parallel_for_(cv::Range(0, int(which.size())), [&](const cv::Range& range) {
        for (int i = range.start; i < range.end; ++i) solve_one(which[size_t(i)]);
      }, double(which.size()));
    }
    if (stopped) std::rethrow_exception(stopped);
  };
  std::vector<size_t> angle, pinhole;
  for (size_t k = 0; k < kinds.size(); ++k) (Traits(kinds[k]).angle ? angle : pinhole).push_back(k);
  solve(angle);
  const std::string beyond = BeyondPinhole(kinds, solved);
  if (beyond.empty()) {
    solve(pinhole);
  } else {
    for (size_t k : pinhole) errors[k] = "not tried: " + beyond;
    Say(options, "models: " + beyond + ": the pinhole-radius models are not tried");
  }
  for (size_t k = 0; k < kinds.size(); ++k) {
    if (solved[k])
      results.solved.push_back(std::move(*solved[k]));
    else
      results.failed.push_back({ModelName(kinds[k]), errors[k], !beyond.empty() && !Traits(kinds[k]).angle});
  }
  if (results.solved.empty() && results.failed.size() == 1)
    throw CalibrationError(results.failed.front().error);
  if (results.solved.empty() && !results.failed.empty()) {
    std::string why = "no model could be solved:";
    for (const ModelFailure& f : results.failed) why += " " + f.model + ": " + f.error + ";";
    why.back() = '.';
    throw CalibrationError(why);
  }
  results.model_selection = ChooseModel(results.solved, results.failed, &results.chosen);
  if (field_after && !results.solved.empty()) {
    const StereoCalibration& solved_radially = results.solved[results.chosen];
    const ModelKind chosen = solved_radially.model;
    const size_t k = size_t(std::find(kinds.begin(), kinds.end(), chosen) - kinds.begin());
    try {
      results.solved[results.chosen] =
          SolveModel(data, options,
                     {chosen, options.nonradial, solved_radially.flow, solved_radially.inconsistent_views,
                      nullptr, radial[k], nullptr});
    } catch (const CalibrationError& e) {  // the radial solution stands
      results.failed.push_back({ModelName(chosen) + " with a non-radial field", e.what()});
    }
  }
  results.solve_seconds = Seconds(start);
  return results;
}

const StereoCalibration& Chosen(const ModelCalibrations& calibrations) {
  return calibrations.solved.at(calibrations.chosen);
}

std::string OutlierLine(const CameraCalibration& camera) {
  if (camera.outliers == 0) return "";
  std::map<int, int> per_view;
  for (const CornerResidual& r : camera.residuals) per_view[r.view] += r.outlier;
  std::string views;
  for (const auto& [view, count] : per_view)
    if (count > 0)
      views += (views.empty() ? "" : ", ") + std::to_string(view) + " (" + std::to_string(count) + ")";
  return camera.name + ": " + std::to_string(camera.outliers) +
         " corners left out as outliers, in views " + views;
}

std::string UncertaintyLine(const CameraCalibration& camera) {
  const ProjectionUncertainty& u = camera.uncertainty;
  const long observed = std::count(u.observed.begin(), u.observed.end(), 1);
  char buf[200];
  std::snprintf(buf, sizeof buf,
                "%s: projection uncertainty (1 sigma, worst direction) median %.4f px, worst "
                "%.4f px over the %ld observed cells of %d x %d",
                camera.name.c_str(), u.median_px, u.worst_px, observed, u.grid.cols, u.grid.rows);
  return buf;
}

double HeldOutRms(const StereoCalibration& c) {
  if (c.mono || c.left.heldout_rms_px < 0) return c.left.heldout_rms_px;
  if (c.right.heldout_rms_px < 0) return -1;
  const double l = c.left.heldout_rms_px, r = c.right.heldout_rms_px;
  return std::sqrt((l * l * c.left.points + r * r * c.right.points) /
                   (c.left.points + c.right.points));
}

std::vector<CornerResidual> Reproject(const CameraModel& model, const CameraData& data,
                                      const std::vector<Pose>& board_poses) {
  const Camera camera(model);
  std::vector<CornerResidual> out;
  for (size_t v = 0; v < data.views.size() && v < board_poses.size(); ++v) {
    const BoardView& view = data.views[v];
    for (int i = 0; i < view.size(); ++i) {
      const auto pixel = camera.Project(board_poses[v] * view.object[i]);
      CornerResidual r;
      r.view = int(v);
      r.index = i;
      r.id = view.ids[i];
      r.observed = view.image[i];
      r.residual = pixel ? Eigen::Vector2d(*pixel - view.image[i]) : Eigen::Vector2d(NAN, NAN);
      out.push_back(r);
    }
  }
  return out;
}

}  // namespace ws::calib
