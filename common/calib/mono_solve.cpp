#include "calib/mono_solve.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <future>
#include <iterator>
#include <opencv2/core/utility.hpp>
#include <optional>

#include "calib/camera_result.h"
#include "calib/evaluate/heldout.h"
#include "calib/solver/corner_noise.h"
#include "calib/solver/outliers.h"
#include "calib/solver/stage_log.h"
#include "calib/start/angle_start.h"
#include "calib/start/pose_fit.h"

namespace ws::calib {
namespace {

// Marks in *disc the corners less than `fraction` of the image's
// half-diagonal from the principal point of `camera`; returns the number of
// views with at least min_points such corners. *everything: whether the disc
// holds every corner.
int MarkDisc(const CameraBlock& camera, const Prepared& p, double fraction, int min_points,
             Inliers* disc, bool* everything) {
  const double radius = fraction * 0.5 * std::hypot(p.width, p.height);
  int views = 0;
  *everything = true;
  for (size_t v = 0; v < p.views.size(); ++v) {
    (*disc)[v].assign(p.views[v].size(), 0);
    if (!p.usable[v]) continue;
    int inside = 0;
    for (int i = 0; i < p.views[v].size(); ++i) {
      const bool in_disc = PixelRadius(camera, p.views[v].image[i]) < radius;
      inside += (*disc)[v][i] = in_disc;
      *everything = *everything && in_disc;
    }
    views += inside >= min_points;
  }
  return views;
}

// The problem of `camera` over the views with at least min_points corners in mask.
Problem MaskedProblem(const CameraBlock& camera, MonoState* s, Inliers* mask, int min_points) {
  Problem problem;
  problem.cameras.push_back(camera);
  problem.warp = s->warp;
  problem.warp.free = false;
  const Prepared& p = s->prepared;
  for (size_t v = 0; v < p.views.size(); ++v)
    if (p.usable[v] && std::count((*mask)[v].begin(), (*mask)[v].end(), 1) >= min_points)
      problem.observations.push_back({0, int(v), &p.views[v], &(*mask)[v], &s->poses[v], false});
  return problem;
}

// How far the model's field must reach: the ideal radius of the image's
// corners under the camera (where the camera cannot invert them yet, their
// distorted radius; not more than 1.5 times the next figure, since a curve
// known only on a disc extrapolates), and of every corner in `mask` under
// its view's pose; times options.r_max_margin. A B-spline is only tame
// (the prior's work) up to its last knot: past it the last cubic piece
// continues.
double FieldRadius(const CameraBlock& camera, const Prepared& p, const Inliers& mask,
                   const std::vector<Pose>& poses, const CalibrationOptions& options) {
  double observed = 0;
  for (size_t v = 0; v < p.views.size(); ++v)
    for (int i = 0; i < p.views[v].size() && p.usable[v]; ++i) {
      if (!mask[v][i]) continue;
      const double r = IdealRadius(camera, poses[v] * p.views[v].object[i]);
      if (std::isfinite(r)) observed = std::max(observed, r);
    }
  const double* in = camera.intrinsics.data();
  double distorted = 0;
  for (double u : {-0.5, p.width - 0.5})
    for (double v : {-0.5, p.height - 0.5})
      distorted = std::max(distorted, std::hypot((u - in[kCx]) / in[kFx], (v - in[kCy]) / in[kFy]));
  const double corners = ImageCornerRadius(camera, p.width, p.height, distorted);
  return std::max(observed, std::min(corners, 1.5 * observed)) * options.r_max_margin;
}

// Clears the mask of the views RefitPoses found bad: they sit out a stage.
void DropBadViews(const std::vector<bool>& good, Inliers* mask) {
  for (size_t v = 0; v < mask->size(); ++v)
    if (!good[v]) std::fill((*mask)[v].begin(), (*mask)[v].end(), 0);
}

// The last stages on every inlier corner: the camera's final problem (the
// board's warp free or held), solved as `settings` say (outlier
// rejection, standard deviations).
void SolveAll(const CameraBlock& camera, const RejectionSettings& settings, bool warp_free,
              const CalibrationOptions& options, MonoState* s) {
  s->problem = MaskedProblem(camera, s, &s->inliers, 1);
  s->problem.warp.free = warp_free;
  s->outcome = SolveWithRejection(s->problem, settings);
  s->warp = s->problem.warp;
  if (s->warp.free)
    Say(options, settings.solve.what + ": board bow x2 " + Fixed(1e3 * s->warp.data[0], 3) +
                     " mm, y2 " + Fixed(1e3 * s->warp.data[1], 3) + " mm");
}

// The board's bow as the options ask it held in the stages before it is
// chosen: free only where it is always estimated.
bool WarpAlwaysFree(const CalibrationOptions& options) {
  return options.board_warp == WarpRule::kEstimated;
}

// A final solve of the camera and its cross-validation, kept aside while
// other candidates are solved (ChooseWarp, ChooseField).
struct FinalSolve {
  CameraBlock camera;
  BoardWarp warp;
  std::vector<Pose> poses;
  Inliers inliers;
  SolveOutcome outcome;
  CrossValidation heldout;
};

FinalSolve Keep(const MonoState& s) {
  return {s.problem.cameras[0], s.warp, s.poses, s.inliers, s.outcome, s.heldout};
}

void Restore(const FinalSolve& kept, MonoState* s) {
  s->warp = kept.warp;
  s->poses = kept.poses;
  s->inliers = kept.inliers;
  s->problem = MaskedProblem(kept.camera, s, &s->inliers, 1);
  s->problem.warp.free = kept.warp.free;
  s->outcome = kept.outcome;
  s->heldout = kept.heldout;
}

// A candidate of ChooseWarp or ChooseField: `camera` (the board's bow free
// or held) solved on the corners as they stand, so that every candidate is
// fitted and cross-validated on the same corners; to the ranking tolerance.
FinalSolve SolveCandidate(const CameraBlock& camera, bool warp_free,
                          const CalibrationOptions& options, const std::string& what,
                          MonoState* s) {
  s->problem = MaskedProblem(camera, s, &s->inliers, 1);
  s->problem.warp.free = warp_free;
  SolveSettings settings = StageSettings(options, what, options.max_iterations);
  settings.tolerance = kRankingTolerance;
  s->outcome = Solve(s->problem, settings);
  s->warp = s->problem.warp;
  s->heldout = CrossValidate(s->problem, options.cv_folds);
  return Keep(*s);
}

// A final solve as a candidate of selection.h: its parameters (the
// camera's, and the bow's where free) and its cross-validation.
Candidate AsCandidate(const std::string& name, const FinalSolve& solve) {
  return Scored(name, int(ParamNames(solve.camera).size()) + (solve.warp.free ? 2 : 0),
                solve.heldout, 0);
}

// A choice made: its lines in the progress, its record in the state.
const Selection& Record(const CalibrationOptions& options, Selection selection, MonoState* s) {
  for (const std::string& line : SelectionLines(selection)) Say(options, line);
  s->selections.push_back(std::move(selection));
  return s->selections.back();
}

// --board-warp auto (options.h, WarpRule::kAuto): the solved flat camera
// solved again with the board's bow free on the same corners, both
// cross-validated on the same folds; the bow is kept where the rule of
// selection.h prefers it to the flat board.
void ChooseWarp(const CalibrationOptions& options, const std::string& what, MonoState* s) {
  if (!s->heldout.folds) s->heldout = CrossValidate(s->problem, options.cv_folds);
  if (!s->heldout.folds) return;  // too few views to cross-validate: the board stays flat
  const FinalSolve flat = Keep(*s);
  const FinalSolve warped = SolveCandidate(flat.camera, true, options, what + " with the bow", s);
  const Selection& selection =
      Record(options,
             Select(s->prepared.name, "board bow",
                    {AsCandidate("the board flat", flat), AsCandidate("the board bowed", warped)}),
             s);
  WarpChoice& choice = s->warp_choice;
  choice.made = selection.candidates[1].failed.empty();
  choice.flat_heldout_px = flat.heldout.rms_px[0];
  choice.warped_heldout_px = warped.heldout.folds ? warped.heldout.rms_px[0] : -1;
  choice.estimated = warped.warp.data;
  SolveOutcome with_stddev;
  EstimateStddev(s->problem, StageSettings(options, what, options.max_iterations), &with_stddev);
  choice.stddev = with_stddev.stddev_warp;
  choice.kept = choice.made && selection.chosen == 1;
  if (!choice.kept) Restore(flat, s);
}

// The median of the usable views' corner noise (corner_noise.h), pixels
// per coordinate.
double UsableViewsNoise(const Prepared& p) {
  std::vector<const BoardView*> views;
  for (size_t v = 0; v < p.views.size(); ++v)
    if (p.usable[v]) views.push_back(&p.views[v]);
  return MedianCornerNoise(views);
}

// The rows of a field of `cols` control points across an image of this
// aspect: as many per unit length, at least NonRadialField's minimum.
int FieldRows(int cols, int width, int height) {
  return std::max(NonRadialField::kDegree + 1, int(std::lround(cols * double(height) / width)));
}

// A field trial not yet solved: the tilt or not, cols x rows control
// points (0 x 0: none) at smoothness lambda.
FieldTrial Trial(bool tilt, int cols, int rows, double lambda) {
  FieldTrial t;
  t.tilt = tilt;
  t.cols = cols;
  t.rows = rows;
  t.smoothness = lambda;
  return t;
}

// Whether `candidate` predicts worse than `best` beyond the spread of
// selection.h (the rule would not take it even as the simpler).
bool WorseBeyondNoise(const FinalSolve& candidate, const FinalSolve& best) {
  return Select("", "", {AsCandidate("", candidate), AsCandidate("", best)}).chosen == 1;
}

// --nonradial (options.h, FieldRule): a given tilt and grid; or, auto, by
// the rule of selection.h: the sensor tilt solved from the radial camera
// against none; then, on top of what that kept and solved from it with
// F = 0 on the same corners, fields cross-validated in two ladders: the
// finest grid of kFieldLadder at each smoothness weight of
// kFieldSmoothnessLadder, smooth to rough, each from the one before; then
// the coarser grids at the weight that predicted best. Each ladder stops
// once two trials in a row predict worse than its best beyond the folds'
// spread (the held-out RMS need not fall steadily: a grid whose knots miss
// the pattern can do worse than a coarser one). The field of the lowest
// held-out RMS is then weighed against none by the rule. No field is tried
// where the held-out RMS exceeds the corners' own noise by no more than it
// resolves (Resolution, selection.h): there is nothing for a field to take
// up (on the simulator's radially symmetric lenses a field gained 0.00002
// px of held-out RMS, consistently over the folds, and moved the
// projection 0.01 px further from the truth).
void ChooseField(const CalibrationOptions& options, FieldRule rule, const std::string& what,
                 int cores, MonoState* s) {
  const Prepared& p = s->prepared;
  const bool warp_free = s->warp.free;
  auto name = [](const FieldTrial& t) {
    const std::string grid = std::to_string(t.cols) + " x " + std::to_string(t.rows) +
                             " field (smoothness " + Fixed(t.smoothness, 3) + ")";
    return t.cols == 0 ? std::string(t.tilt ? "the sensor tilt" : "none")
                       : (t.tilt ? "the sensor tilt and a " : "a ") + grid;
  };
  // The field t added to `from` (its rectangle and prior at from's
  // parameters) and solved; with `start`, a solve of the same grid, from
  // that solution (the same problem, a nearer start: it converges in fewer
  // steps).
  auto solve = [&](const CameraBlock& from, const FieldTrial& t, const CameraBlock* start, MonoState* state) {
    CameraBlock camera = WithNonRadialField(from, t.cols, t.rows, t.tilt, p.width, p.height, t.smoothness);
    if (start) {
      camera.intrinsics = start->intrinsics;
      camera.coeffs = start->coeffs;
    }
    return SolveCandidate(camera, warp_free, options, what + " with " + name(t), state);
  };
  const double given = options.spline.smoothness;
  if (rule == FieldRule::kGrid) {
    solve(s->problem.cameras[0],
          Trial(options.field_tilt, options.field_cols, options.field_rows, given), nullptr, s);
    return;
  }
  if (!s->heldout.folds) s->heldout = CrossValidate(s->problem, options.cv_folds);
  if (!s->heldout.folds) return;  // too few views to cross-validate: radial only
  // The candidates solved, none first, each with its point on the field
  // curve (the same index in both).
  std::vector<FinalSolve> candidates = {Keep(*s)};
  s->field_curve.push_back({false, 0, 0, 0, Rms(Residuals(s->problem, 0)), s->heldout.rms_px[0],
                           s->heldout.fold_rms_px[0]});
  // A trial solved on a copy of the state from `start` (the solve it starts
  // from), so that trials can run at once: its solve, or why not.
  struct Solved {
    std::optional<FinalSolve> solve;
    FieldTrial trial;
    std::string error;
  };
  auto solve_from = [&](const FinalSolve& start, const CameraBlock& from, FieldTrial t,
                        const CameraBlock* warm) {
    MonoState state = *s;
    Restore(start, &state);
    Solved out{std::nullopt, t, ""};
    try {
      out.solve = solve(from, t, warm, &state);
      out.trial.rms_px = Rms(Residuals(state.problem, 0));
    } catch (const CalibrationError& e) {
      out.error = e.what();
    }
    return out;
  };
  // A trial's outcome recorded: kept where the views hold it (every fold
  // solved, a finite held-out RMS), with its point on the field curve (the
  // same index in both).
  auto keep = [&](Solved solved) {
    if (!solved.solve) {
      Say(options, what + " with " + name(solved.trial) + ": " + solved.error);
      return false;
    }
    const CrossValidation& cv = solved.solve->heldout;
    if (cv.folds != candidates[0].heldout.folds || !std::isfinite(cv.rms_px[0]))
      return false;  // a field the views cannot hold
    solved.trial.heldout_rms_px = cv.rms_px[0];
    solved.trial.fold_rms_px = cv.fold_rms_px[0];
    s->field_curve.push_back(solved.trial);
    candidates.push_back(std::move(*solved.solve));
    return true;
  };
  auto tried = [&](const CameraBlock& from, FieldTrial t) {
    return keep(solve_from(Keep(*s), from, t, nullptr));
  };
  auto candidate = [&](size_t i) { return AsCandidate(name(s->field_curve[i]), candidates[i]); };
  // The tilt against none.
  size_t base = 0;
  if (tried(candidates[0].camera, Trial(true, 0, 0, 0)) &&
      Record(options, Select(p.name, "sensor tilt", {candidate(0), candidate(1)}), s).chosen == 1)
    base = 1;
  const bool tilt = base == 1;
  // A field only where the lens leaves something to take up: the held-out
  // RMS above the corners' own noise (corner_noise.h, per corner sqrt(2)
  // sigma: an upper bound where the lens bends the rows) by more than the
  // held-out RMS resolves. Else none, and no field is solved.
  // (Values, not references: the ladders below grow `candidates`.)
  const Candidate radial = candidate(base);
  const double resolution = Resolution(radial);
  const double floor_px = std::sqrt(2.0) * UsableViewsNoise(p);
  const double excess_px = std::sqrt(std::max(
      0.0, radial.heldout_rms_px * radial.heldout_rms_px - floor_px * floor_px));
  if (!(excess_px > resolution)) {
    s->field_chosen = int(base);
    Say(options, what + ": no field tried: the held-out RMS " + Fixed(radial.heldout_rms_px) +
                     " px is within " + Fixed(resolution) + " px of the corners' own noise, " +
                     Fixed(floor_px) + " px");
    Restore(candidates[base], s);
    return;
  }
  // One ladder of fields solved from the base, in order, until two in a row
  // predict worse than the best of the ladder beyond the spread; returns
  // the candidate of its lowest held-out RMS (0: none solved). The trials
  // run `cores` at a time, each from the same start (the ladder judged in
  // order, so a stop wastes at most the ones solved beside it). With
  // `one_grid` (the weights of one grid), each group from the newest solve
  // before it.
  int fields = 0;  // solved so far, for the progress lines
  const int most_fields = int(std::size(kFieldSmoothnessLadder) + std::size(kFieldLadder) - 1);
  const auto fields_start = std::chrono::steady_clock::now();
  const size_t at_once = size_t(std::max(cores, 1));
  auto climb = [&](const std::vector<FieldTrial>& ladder, bool one_grid) {
    size_t best = 0;
    int worse_in_a_row = 0;
    for (size_t first = 0; first < ladder.size() && worse_in_a_row < 2; first += at_once) {
      const bool warm = one_grid && best != 0;
      const FinalSolve start = candidates[warm ? candidates.size() - 1 : base];
      std::vector<Solved> group(std::min(at_once, ladder.size() - first));
      cv::parallel_for_(cv::Range(0, int(group.size())), [&](const cv::Range& range) {
        for (int j = range.start; j < range.end; ++j)
          group[size_t(j)] = solve_from(start, candidates[base].camera, ladder[first + size_t(j)],
                                       warm ? &start.camera : nullptr);
      }, double(group.size()));
      for (Solved& solved : group) {
        if (worse_in_a_row == 2) break;
        if (!keep(std::move(solved))) return best;
        const FinalSolve& newest = candidates.back();
        ++fields;
        Say(options, what + " with " + name(s->field_curve.back()) + ": held-out " +
                         Fixed(newest.heldout.rms_px[0]) + " px (field " + std::to_string(fields) +
                         " of at most " + std::to_string(most_fields) + ", " +
                         TimeLeft(fields_start, fields, most_fields) + " at most; " +
                         newest.outcome.message + ")");
        if (best == 0) {
          best = candidates.size() - 1;
          continue;
        }
        worse_in_a_row = WorseBeyondNoise(newest, candidates[best]) ? worse_in_a_row + 1 : 0;
        if (newest.heldout.rms_px[0] < candidates[best].heldout.rms_px[0]) best = candidates.size() - 1;
      }
    }
    return best;
  };
  const int finest = std::end(kFieldLadder)[-1];
  const int finest_rows = FieldRows(finest, p.width, p.height);
  std::vector<FieldTrial> weights;
  for (double lambda : kFieldSmoothnessLadder)
    weights.push_back(Trial(tilt, finest, finest_rows, lambda));
  const size_t smoothest_best = climb(weights, true);
  const double lambda = smoothest_best ? s->field_curve[smoothest_best].smoothness : given;
  std::vector<FieldTrial> grids;
  for (int cols : kFieldLadder)
    if (cols != finest)
      grids.push_back(Trial(tilt, cols, FieldRows(cols, p.width, p.height), lambda));
  climb(grids, false);
  // The field's shape (grid and smoothness) is the one of the lowest
  // held-out RMS of the ladders (a penalised spline's smoothness chosen by
  // cross-validation: Eilers and Marx); whether the lens has a field at
  // all is the choice of the rule, that field against none.
  size_t shape = 0;  // 0: no field solved (the fields follow none and the tilt)
  for (size_t i = 2; i < candidates.size(); ++i)
    if (shape == 0 || candidates[i].heldout.rms_px[0] < candidates[shape].heldout.rms_px[0]) shape = i;
  size_t chosen = base;
  if (shape != 0 &&
      Record(options, Select(p.name, "field", {candidate(base), candidate(shape)}), s).chosen == 1)
    chosen = shape;
  s->field_chosen = int(chosen);
  Restore(candidates[chosen], s);
}

// --knots auto (options.h): each count of kKnotLadder solved on every
// inlier corner from the solved curve (ForField over the same field, no
// outlier rejection, to kRankingTolerance) and cross-validated, until two
// counts in a row do no better than the best held-out RMS while fitting
// about as well as the best fit (kMissedFit); then the count the rule of
// selection.h keeps solved as any count is (SolveAll). The counts run
// `cores` at a time, each on a copy of the state from the same start; the
// ladder is judged in order, so a stop wastes at most the ones solved
// beside it, and the outcome is the one of the counts solved one by one.
void ChooseKnots(const CalibrationOptions& options, const std::string& what, int cores,
                 MonoState* s) {
  const SplineOptions& asked = options.spline;
  const CameraBlock solved = s->problem.cameras[0];
  const double r_max = FieldEnd(solved);
  struct Count {
    CameraBlock camera;
    double rms_px;
    CrossValidation heldout;
  };
  const MonoState start = *s;  // read by the counts beside this thread, which writes *s
  auto solve_count = [&](int knots) {
    MonoState state = start;
    state.problem = MaskedProblem(ForField(solved, {knots, asked.degree, asked.smoothness}, r_max),
                                  &state, &state.inliers, 1);
    SolveSettings settings =
        StageSettings(options, what + " with " + std::to_string(knots) + " knots", options.max_iterations);
    settings.tolerance = kRankingTolerance;
    Solve(state.problem, settings);
    return Count{state.problem.cameras[0], Rms(Residuals(state.problem, 0)),
                 CrossValidate(state.problem, options.cv_folds)};
  };
  std::vector<CameraBlock> solves;
  std::vector<CrossValidation> cvs;
  size_t best = 0;
  double best_fit = INFINITY;  // the lowest fitted RMS so far
  int saturated = 0;           // counts in a row that fit about as well as the best fit
  bool stopped = false;
  const int most = int(std::size(kKnotLadder));
  const int at_once = std::max(cores, 1);
  const auto knots_start = std::chrono::steady_clock::now();
  for (int first = 0; first < most && !stopped; first += at_once) {
    // The group's first count on this thread, the others beside it.
    std::vector<std::future<Count>> group;
    for (int j = first; j < std::min(first + at_once, most); ++j)
      group.push_back(std::async(j == first ? std::launch::deferred : std::launch::async, solve_count,
                                 kKnotLadder[j]));
    for (size_t j = 0; j < group.size() && !stopped; ++j) {
      Count count = group[j].get();
      const int knots = kKnotLadder[first + int(j)];
      const CrossValidation& cv = count.heldout;
      if (cv.folds == 0) throw CalibrationError(what + ": too few views to cross-validate the knots");
      s->knot_curve.push_back({knots, count.rms_px, cv.rms_px[0], cv.fold_rms_px[0]});
      const int tried = int(solves.size()) + 1;
      Say(options, what + " with " + std::to_string(knots) + " knots: rms " + Fixed(count.rms_px) +
                       " px, held-out " + Fixed(cv.rms_px[0]) + " px (count " + std::to_string(tried) +
                       " of at most " + std::to_string(most) + ", " +
                       TimeLeft(knots_start, tried, most) + " at most)");
      solves.push_back(count.camera);
      cvs.push_back(cv);
      if (cv.rms_px[0] < s->knot_curve[best].heldout_rms_px) best = solves.size() - 1;
      best_fit = std::min(best_fit, count.rms_px);
      saturated = count.rms_px <= kMissedFit * best_fit ? saturated + 1 : 0;
      stopped = solves.size() >= best + 3 && saturated >= 2;
    }
  }
  std::vector<Candidate> counts;
  for (size_t i = 0; i < solves.size(); ++i)
    counts.push_back(Scored(std::to_string(s->knot_curve[i].knots) + " knots",
                            int(ParamNames(solves[i]).size()), cvs[i], 0));
  const int chosen = Record(options, Select(s->prepared.name, "knots", counts), s).chosen;
  SolveAll(solves[chosen], OnTheCorners(options, what), WarpAlwaysFree(options), options, s);
  s->heldout = cvs[chosen];
}

// The radial model up to its field: the start (plan.angle_starts's of
// camera_slot where shared), the continuation, the outliers, the knots
// (`cores` at once) and the board's bow.
void SolveRadial(const CameraData& data, const BoardExtent& board, const CalibrationOptions& options,
                 const ModelPlan& plan, int camera_slot, int cores, MonoState* s) {
  // The model (knots, the board's bow, the field) is chosen with no
  // standard deviations on the corners the radial model keeps (OnTheCorners:
  // a board misdetected or bent far beyond a bow would otherwise decide
  // every held-out RMS); the final solve decides every corner anew with the
  // chosen model, so a corner only a richer one fits comes back.
  // --knots auto: the continuation runs on kContinuationKnots.
  const bool auto_knots = !options.spline.knots;
  const SplineOptions spline =
      auto_knots ? SplineOptions{kContinuationKnots, options.spline.degree, options.spline.smoothness}
                 : options.spline;
  s->prepared = Prepare(data, options);
  s->warp = BoardWarp{{0, 0}, board, false};
  Prepared& p = s->prepared;
  RequireViews(p, options.min_views);
  const Init init = Initialize(p, options, plan.model,
                               plan.angle_starts ? &plan.angle_starts->camera[camera_slot] : nullptr);
  s->poses = init.poses;
  s->inliers.assign(p.views.size(), {});
  for (size_t v = 0; v < p.views.size(); ++v) s->inliers[v].assign(p.views[v].size(), 1);
  s->init_method = init.pinhole.method;
  const std::string what = p.name + " camera (" + ModelName(plan.model) + ")";
  const int min_points = options.min_points_per_view;

  // The start's lens on the central disc, only fx fy cx cy free.
  CameraBlock pinhole = StartCamera(init, p, plan.model, spline);
  Inliers disc(p.views.size());
  bool everything = false;
  double fraction = 0.25;
  while (MarkDisc(pinhole, p, fraction, min_points, &disc, &everything) < options.min_views &&
         !everything)
    fraction *= 1.4;
  // Poses from Zhang's K can be far off for a strongly distorted lens: the
  // fit alternates with refitting each view's pose, while that helps.
  for (double previous = INFINITY;;) {
    Problem stage = MaskedProblem(pinhole, s, &disc, min_points);
    Solve(stage, StageSettings(options, what + " pinhole start", 50));
    pinhole = stage.cameras[0];
    const double rms = Rms(Residuals(stage, 0));
    Say(options, what + ": pinhole fit of " + std::to_string(stage.observations.size()) +
                     " views within " + Fixed(fraction, 2) + " of the half-diagonal: rms " +
                     Fixed(rms) + " px, fx " + Fixed(pinhole.intrinsics[kFx], 2));
    if (!(rms < 0.9 * previous)) break;
    previous = rms;
    DropBadViews(RefitPoses(pinhole, p, init, disc, false, options, what, &s->poses), &disc);
  }
  RefitPoses(pinhole, p, init, s->inliers, true, options, what, &s->poses);

  // The full model on growing discs, its field (the B-spline's knots) over
  // the image as the camera sees it, grown with the discs. A polynomial's
  // coefficients are global, and the high orders fitted to a small disc
  // explode outside it: one more of them is freed with each disc.
  double r_max = ImageCornerRadius(pinhole, p.width, p.height, 1.0) * options.r_max_margin;
  CameraBlock camera = ForField(pinhole, spline, r_max);
  auto cover = [&](const Inliers& mask) {
    const double needed = FieldRadius(camera, p, mask, s->poses, options);
    if (!(needed > 1.05 * r_max)) return;
    r_max = needed;
    camera = ForField(camera, spline, r_max);
  };
  const bool global_coeffs = !Traits(KindOf(camera.model)).spline;
  for (int stage = 1; !everything; ++stage) {
    fraction *= 1.4;
    MarkDisc(pinhole, p, fraction, min_points, &disc, &everything);
    DropBadViews(RefitPoses(camera, p, init, disc, false, options, what, &s->poses), &disc);
    cover(disc);
    camera.free_coeffs = global_coeffs ? stage : -1;
    Problem stage_problem = MaskedProblem(camera, s, &disc, min_points);
    Solve(stage_problem,
          StageSettings(options, what + " within " + Fixed(fraction, 2), options.max_iterations));
    camera = stage_problem.cameras[0];
    Say(options, what + ": " + std::to_string(stage_problem.observations.size()) +
                     " views within " + Fixed(fraction, 2) + " of the half-diagonal: rms " +
                     Fixed(Rms(Residuals(stage_problem, 0))) + " px, fx " +
                     Fixed(camera.intrinsics[kFx], 2) + ", r_max " + Fixed(r_max, 3));
  }
  camera.free_coeffs = -1;

  // Every corner, without the views that still fit badly.
  const std::vector<bool> good =
      RefitPoses(camera, p, init, s->inliers, false, options, what, &s->poses);
  for (size_t v = 0; v < good.size(); ++v)
    if (!good[v]) p.Skip(int(v), "no board pose fits its corners (a mirrored or partial view?)");
  RequireViews(p, options.min_views);
  cover(s->inliers);
  SolveAll(camera, OnTheCorners(options, what), WarpAlwaysFree(options), options, s);
  Say(options, what + ": r_max " + Fixed(r_max, 3) + ", rms " +
                   Fixed(Rms(Residuals(s->problem, 0))) + " px (" + s->outcome.message + ")");

  // The field once more as the solved camera sees it, if that differs by
  // more than 5 %.
  const CameraBlock& solved = s->problem.cameras[0];
  const double needed = FieldRadius(solved, p, s->inliers, s->poses, options);
  if (std::abs(needed - r_max) > 0.05 * r_max) {
    SolveAll(ForField(solved, spline, needed), OnTheCorners(options, what), WarpAlwaysFree(options),
             options, s);
    Say(options, what + ": field moved to r_max " + Fixed(needed, 3) + ", rms " +
                     Fixed(Rms(Residuals(s->problem, 0))) + " px");
  }
  // A curve that folds back inside the observed field on every corner
  // cannot follow the lens (a pinhole radius cannot reach 90 degrees): the
  // knots, the bow and a field move it too little to unfold it, and leaving
  // out the corners past the fold as outliers would only hide that. It
  // fails the final check (camera_result.h) now instead of after them.
  RequireUnfolded(s->problem, 0, p.name);
  if (options.outliers != OutlierRule::kOff)  // the radial model's outliers
    SolveAll(s->problem.cameras[0], RejectingOutliers(options, what + " (gross outliers)"),
             WarpAlwaysFree(options), options, s);
  if (auto_knots && Traits(KindOf(s->problem.cameras[0].model)).spline) ChooseKnots(options, what, cores, s);
  if (options.board_warp == WarpRule::kAuto) ChooseWarp(options, what, s);
}

}  // namespace

void SolveMono(const CameraData& data, const BoardExtent& board, const CalibrationOptions& options,
               const ModelPlan& plan, MonoState* s, int camera, int cores) {
  if (plan.from_radial) {
    const MonoState& radial = plan.from_radial->camera[camera];
    *s = radial;
    Restore(Keep(radial), s);  // its problem over this state's own views
  } else {
    SolveRadial(data, board, options, plan, camera, cores, s);
    if (plan.keep_radial) plan.keep_radial->camera[camera] = *s;
  }
  const std::string what = s->prepared.name + " camera (" + ModelName(plan.model) + ")";
  if (plan.nonradial != FieldRule::kNone) ChooseField(options, plan.nonradial, what, cores, s);
  // The final solve: the chosen model, its outliers left out. Then its
  // standard deviations and its cross-validation, side by side where there
  // are cores for both: each reads the solution and writes its own.
  SolveAll(s->problem.cameras[0], RejectingOutliers(options, what), s->warp.free, options, s);
  RequireUnfolded(s->problem, 0, s->prepared.name);  // before the cross-validation it would waste
  const Problem solved = s->problem;
  std::future<CrossValidation> heldout =
      std::async(cores > 1 ? std::launch::async : std::launch::deferred,
                 [&] { return CrossValidate(solved, options.cv_folds); });
  if (options.covariance)
    EstimateStddev(s->problem, StageSettings(options, what, options.max_iterations), &s->outcome);
  s->heldout = heldout.get();
}

CrossValidation HeldOut(const MonoState& state, const CalibrationOptions& options) {
  return state.heldout.folds ? state.heldout
                             : CrossValidate(state.problem, options.cv_folds);
}

}  // namespace ws::calib
