// Cross-validation (issue #14, calib/evaluate/heldout.h): a held-out RMS tells a
// model that follows the lens from one that follows the noise of the views
// it saw.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numeric>
#include <random>
#include <string>
#include <utility>

#include "calib/calibrate.h"
#include "calib/evaluate/heldout.h"
#include "calib/evaluate/selection.h"
#include "calib_test_rigs.h"

namespace {

using namespace ws::calib;
using namespace ws::calib::test;

TEST(CrossValidation, AnOverfittingSplineShowsItAndTheChosenOneDoesNot) {
  SyntheticRigOptions truth = MustacheRig();
  truth.views = 12;  // few views
  const SyntheticRig rig = MakeSyntheticRig(truth);
  CalibrationOptions overfit;
  overfit.spline.knots = 31;  // many coefficients, no prior to tame them
  overfit.spline.smoothness = 0;
  overfit.covariance = false;
  const CameraCalibration wild = CalibrateCamera(rig.data.left, overfit);
  CalibrationOptions automatic;
  automatic.covariance = false;
  const CameraCalibration chosen = CalibrateCamera(rig.data.left, automatic);
  for (const CameraCalibration* c : {&wild, &chosen})
    std::printf("%zu coefficients: rms %.4f px, held-out %.4f px over %zu folds\n",
                c->param_names.size() - 6, c->rms_px, c->heldout_rms_px,
                c->heldout_fold_rms_px.size());
  ASSERT_EQ(wild.heldout_fold_rms_px.size(), 5u);
  EXPECT_GT(wild.heldout_rms_px, 1.5 * wild.rms_px);
  EXPECT_LE(chosen.heldout_rms_px, 1.15 * chosen.rms_px);
  EXPECT_LT(chosen.heldout_rms_px, wild.heldout_rms_px);
  EXPECT_FALSE(chosen.knot_curve.empty());
}

// Every view but one keeps only its corners within 300 px of the image
// centre: held out, that one view's outer corners lie past every training
// corner, where the fold's curve only extrapolates; they are left out of
// the held-out RMS and counted.
TEST(CrossValidation, CornersPastTheTrainingFieldAreLeftOutAndCounted) {
  const SyntheticRig rig = MakeSyntheticRig(MustacheRig());
  CameraData data = rig.data.left;
  const Eigen::Vector2d centre(0.5 * (data.image_width - 1), 0.5 * (data.image_height - 1));
  constexpr double kField = 300;
  size_t lone = data.views.size(), outer = 0;
  for (size_t v = 0; v < data.views.size(); ++v) {
    BoardView& view = data.views[v];
    int beyond = 0;
    for (const Eigen::Vector2d& u : view.image) beyond += (u - centre).norm() > kField + 50;
    if (lone == data.views.size() && beyond >= 10) {
      lone = v;
      outer = beyond;
      continue;
    }
    BoardView inner;
    for (int i = 0; i < view.size(); ++i)
      if ((view.image[i] - centre).norm() <= kField) {
        inner.ids.push_back(view.ids[i]);
        inner.object.push_back(view.object[i]);
        inner.image.push_back(view.image[i]);
      }
    view = inner;
  }
  ASSERT_LT(lone, data.views.size()) << "no view reaches past the field";
  CalibrationOptions options;
  options.spline.knots = 13;
  options.covariance = false;
  const CameraCalibration result = CalibrateCamera(data, options);
  std::printf("view %zu alone reaches past %.0f px (%zu corners 50 px past it): %d held-out "
              "corners left out; rms %.4f px, held-out %.4f px\n",
              lone, kField, outer, result.heldout_extrapolated, result.rms_px, result.heldout_rms_px);
  EXPECT_GE(result.heldout_extrapolated, int(outer));
  // The whole rig covers its field: nothing is left out.
  const CameraCalibration whole = CalibrateCamera(rig.data.left, options);
  EXPECT_LT(whole.heldout_extrapolated, 10);
}

// A candidate of selection.h with these per-fold held-out RMS over
// `corners` held-out corners.
Candidate Folds(const std::string& name, std::vector<double> folds, int corners = 1000000) {
  Candidate c;
  c.name = name;
  c.parameters = int(folds.size());
  double sum = 0;
  for (double f : folds) sum += f * f;
  c.heldout_rms_px = std::sqrt(sum / double(folds.size()));
  c.fold_rms_px = std::move(folds);
  c.corners = corners;
  return c;
}

TEST(Selection, ARicherCandidateWinsOnlyBeyondTheFoldNoise) {
  // Per fold: a clearly worse first candidate, a second within the noise
  // of the best third, a fourth worse again.
  const Selection s = Select("left", "knots",
                             {Folds("7 knots", {0.20, 0.22, 0.21, 0.19, 0.20}),
                              Folds("9 knots", {0.101, 0.100, 0.102, 0.100, 0.098}),
                              Folds("11 knots", {0.100, 0.100, 0.100, 0.100, 0.100}),
                              Folds("13 knots", {0.105, 0.104, 0.106, 0.105, 0.104})});
  EXPECT_EQ(s.best, 2);
  EXPECT_EQ(s.chosen, 1);
  // 9 beats 7 far beyond the spread; 11 does better than 9 by less than it.
  EXPECT_EQ(s.candidates[1].against, 0);
  EXPECT_GT(-s.candidates[1].excess_px, s.candidates[1].spread_px);
  EXPECT_EQ(s.candidates[2].against, 1);
  EXPECT_LE(-s.candidates[2].excess_px, s.candidates[2].spread_px);
  // The lines name every candidate, mark the winner and say why.
  const std::vector<std::string> lines = SelectionLines(s);
  ASSERT_EQ(lines.size(), 5u);
  EXPECT_NE(lines[1].find("9 knots"), std::string::npos);
  EXPECT_NE(lines[1].find("<- chosen"), std::string::npos);
  EXPECT_NE(lines[4].find("9 knots beats 7 knots by"), std::string::npos) << lines[4];
  EXPECT_NE(lines[4].find("the lowest held-out RMS is 11 knots'"), std::string::npos) << lines[4];
  // A second candidate consistently 2 % better than the first is beyond
  // the noise: every fold says so.
  EXPECT_EQ(Select("", "", {Folds("a", {0.102, 0.1122, 0.0918, 0.102, 0.1071}),
                            Folds("b", {0.100, 0.110, 0.090, 0.100, 0.105})})
                .chosen,
            1);
  EXPECT_EQ(Select("", "", {}).chosen, -1);
}

TEST(Selection, AGainWithinTheFoldNoiseDoesNotWin) {
  // The richer candidate is better on average, by 0.0004 px, but the folds
  // disagree by more than that: the simpler wins. The same gain in every
  // fold wins.
  const std::vector<double> simple = {0.1005, 0.0995, 0.1012, 0.0998, 0.1010};
  const std::vector<double> noisy = {0.1000, 0.1001, 0.0990, 0.1000, 0.1009};
  const Selection s = Select("", "field", {Folds("none", simple), Folds("a field", noisy)});
  EXPECT_EQ(s.chosen, 0);
  EXPECT_LT(s.candidates[1].excess_px, 0.0);
  EXPECT_LE(-s.candidates[1].excess_px, s.candidates[1].spread_px);
  std::vector<double> steady = simple;
  for (double& f : steady) f -= 0.0004;
  EXPECT_EQ(Select("", "field", {Folds("none", simple), Folds("a field", steady)}).chosen, 1);
}

TEST(Selection, ACandidateWithoutEveryFoldIsNotScored) {
  Candidate failed;
  failed.name = "poly6";
  failed.failed = "the solver did not reach a valid camera";
  const Selection s = Select("", "model",
                             {failed, Folds("kb4", {0.2, 0.2, 0.2}), Folds("bspline", {0.1, 0.1})});
  EXPECT_EQ(s.chosen, 1);
  EXPECT_EQ(s.candidates[2].failed, "not every fold could be solved");
  EXPECT_NE(SelectionLines(s)[0].find("not scored: the solver did not reach"), std::string::npos);
}

TEST(Selection, TheResolutionIsTheSpreadOfTheHeldOutRmsOfFreshCorners) {
  // Held-out RMS of n corners of Gaussian noise, drawn afresh many times:
  // its spread is what Resolution says, of any one draw.
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.3);
  const int n = 2000, draws = 400;
  std::vector<double> rms;
  double resolution = 0;
  for (int d = 0; d < draws; ++d) {
    CrossValidation cv;
    cv.folds = 5;
    double sum = 0;
    for (int i = 0; i < n; ++i) {
      const double ex = noise(rng), ey = noise(rng);
      cv.corners.push_back({0, i / 40, i % 40, i % 5, ex * ex + ey * ey});
      cv.corners.push_back({1, i / 40, i % 40, i % 5, 1.0});  // another camera's: not counted
      sum += ex * ex + ey * ey;
    }
    cv.rms_px = {std::sqrt(sum / n), 1.0};
    cv.fold_rms_px = {{cv.rms_px[0]}, {1.0}};
    rms.push_back(cv.rms_px[0]);
    resolution += Resolution(Scored("", 0, cv, 0)) / draws;
  }
  const double mean = std::accumulate(rms.begin(), rms.end(), 0.0) / draws;
  double var = 0;
  for (double r : rms) var += (r - mean) * (r - mean) / (draws - 1);
  std::printf("held-out RMS of %d corners: spread %.5f px, resolution %.5f px\n", n, std::sqrt(var),
              resolution);
  EXPECT_NEAR(resolution, std::sqrt(var), 0.1 * std::sqrt(var));
  EXPECT_EQ(Resolution(Scored("", 0, CrossValidation{}, 0)), 0.0);
}

}  // namespace
