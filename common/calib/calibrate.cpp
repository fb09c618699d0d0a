#include "calib/calibrate.h"

#include <algorithm>
#include <chrono>
#include <climits>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>

#include "calib/camera_result.h"
#include "calib/evaluate/heldout.h"
#include "calib/mono_solve.h"
#include "calib/solver/stage_log.h"
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

CameraCalibration CalibrateCamera(const CameraData& data, const CalibrationOptions& options) {
  CheckOptions(options);
  MonoState state;
  SolveMono(data, ExtentOf({&data}), options, &state);
  CameraCalibration result =
      CameraResult(state.problem, 0, state.prepared, state.outcome, state.init_method, options);
  result.knot_curve = state.knot_curve;
  result.warp_choice = state.warp_choice;
  result.field_curve = state.field_curve;
  result.field_chosen = state.field_chosen;
  SetHeldOut(HeldOut(state, options), 0, &result);
  return result;
}

StereoCalibration CalibrateStereo(const StereoData& data, const CalibrationOptions& options) {
  CheckOptions(options);
  const auto start = std::chrono::steady_clock::now();
  // No right image at all (not merely no board in it): a one-camera rig.
  const bool mono = data.right.image_width == 0 &&
                    std::all_of(data.right.views.begin(), data.right.views.end(),
                                [](const BoardView& view) { return view.empty(); });
  StereoCalibration result;
  if (mono) {
    result.model = options.model;
    result.mono = true;
    result.left = CalibrateCamera(data.left, options);
    result.rms_px = result.left.rms_px;  // the rig's RMS is its one camera's
  } else {
    result = SolveStereo(data, options);
  }
  result.solve_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
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

// ModelCalibrations::chosen: of the models that use the most views (a held-out
// RMS over fewer views, e.g. a pinhole model's that cannot reach past 90
// degrees, is not comparable) and leave out no more corners as outliers than
// the fewest any of them does plus its Poisson noise (3 sqrt(n + 1): a model
// that cannot follow the lens leaves out the corners it misses, and would
// be compared where it can), ordered by parameter count, each fold's RMS on
// the corners they all kept (FoldRmsOnCommonCorners) pooled over the
// cameras, ChooseWithinNoise. Where a model was not cross-validated (fewer
// than 4 views), the one of the lowest FittedNoise, the cameras pooled.
int ChooseModel(const std::vector<StereoCalibration>& solved) {
  auto views = [](const StereoCalibration& c) { return c.left.views + (c.mono ? 0 : c.right.views); };
  auto outliers = [](const StereoCalibration& c) {
    return c.left.outliers + (c.mono ? 0 : c.right.outliers);
  };
  int most = 0;
  for (const auto& c : solved) most = std::max(most, views(c));
  int fewest = INT_MAX;
  for (const auto& c : solved)
    if (views(c) == most) fewest = std::min(fewest, outliers(c));
  std::vector<int> order;
  for (size_t i = 0; i < solved.size(); ++i)
    if (views(solved[i]) == most && outliers(solved[i]) <= fewest + 3 * std::sqrt(fewest + 1.0))
      order.push_back(int(i));
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return solved[a].left.param_names.size() < solved[b].left.param_names.size();
  });
  const bool cross_validated = std::all_of(solved.begin(), solved.end(), [](const auto& c) {
    return !c.left.heldout_fold_rms_px.empty() && (c.mono || !c.right.heldout_fold_rms_px.empty());
  });
  if (!cross_validated) {
    auto noise = [](const StereoCalibration& c) {
      return c.mono ? FittedNoise(c.left) : std::hypot(FittedNoise(c.left), FittedNoise(c.right));
    };
    return *std::min_element(order.begin(), order.end(),
                             [&](int a, int b) { return noise(solved[a]) < noise(solved[b]); });
  }
  std::vector<std::vector<double>> folds;
  for (const bool right : {false, true}) {
    if (right && solved.front().mono) break;
    std::vector<const std::vector<HeldOutCorner>*> corners;
    for (int i : order) corners.push_back(&(right ? solved[i].right : solved[i].left).heldout_corners);
    const auto rms = FoldRmsOnCommonCorners(corners, 0);
    if (!right) {
      folds = rms;
      continue;
    }
    for (size_t i = 0; i < folds.size(); ++i)
      for (size_t k = 0; k < folds[i].size() && k < rms[i].size(); ++k)
        folds[i][k] = std::hypot(folds[i][k], rms[i][k]) / std::sqrt(2.0);
  }
  return order[ChooseWithinNoise(folds)];
}

}  // namespace

ModelCalibrations CalibrateStereoAllModels(const StereoData& data,
                                           const CalibrationOptions& options,
                                           const std::vector<ModelKind>& kinds) {
  ModelCalibrations results;
  // Several models are compared radially; the chosen one then gets its
  // non-radial field.
  const bool field_after = kinds.size() > 1 && options.nonradial != FieldRule::kNone;
  for (const auto& kind : kinds) {
    CalibrationOptions o = options;
    o.model = kind;
    if (field_after) o.nonradial = FieldRule::kNone;
    try {
      results.solved.push_back(CalibrateStereo(data, o));
    } catch (const CalibrationError& e) {
      results.failed.push_back({ModelName(kind), e.what()});
    }
  }
  if (results.solved.empty() && !results.failed.empty())
    throw CalibrationError(results.failed.front().error);
  results.chosen = ChooseModel(results.solved);
  if (field_after && !results.solved.empty()) {
    CalibrationOptions o = options;
    o.model = results.solved[results.chosen].model;
    try {
      results.solved[results.chosen] = CalibrateStereo(data, o);
    } catch (const CalibrationError& e) {  // the radial solution stands
      results.failed.push_back({ModelName(o.model) + " with a non-radial field", e.what()});
    }
  }
  return results;
}

const StereoCalibration& Chosen(const ModelCalibrations& calibrations) {
  return calibrations.solved.at(calibrations.chosen);
}

std::string KnotChoiceLine(const CameraCalibration& camera) {
  char buf[64];
  std::string curve;
  for (const KnotTrial& t : camera.knot_curve) {
    std::snprintf(buf, sizeof buf, "%s%d: %.4f", curve.empty() ? "" : ", ", t.knots,
                  t.heldout_rms_px);
    curve += buf;
  }
  return camera.name + ": " + std::to_string(int(camera.param_names.size()) - 6) +
         " coefficients chosen by " + std::to_string(camera.heldout_fold_rms_px.size()) +
         "-fold cross-validation (the fewest within the fold-to-fold noise of the lowest "
         "held-out RMS); held-out RMS per count " + curve + " px";
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

std::string WarpChoiceLine(const CameraCalibration& camera) {
  const WarpChoice& w = camera.warp_choice;
  if (!w.made) return "";
  auto mm = [&](int k) {
    return Fixed(1e3 * w.estimated[k], 3) +
           (w.stddev.size() == 2 ? " +- " + Fixed(1e3 * w.stddev[k], 3) : "") + " mm";
  };
  return camera.name + ": board bow " + (w.kept ? "kept" : "left out") + " (held-out RMS " +
         Fixed(w.warped_heldout_px) + " px with it, " + Fixed(w.flat_heldout_px) +
         " px flat), x2 " + mm(0) + ", y2 " + mm(1);
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
