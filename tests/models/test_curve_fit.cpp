#include <gtest/gtest.h>

#include <cmath>

#include "models/bspline_basis.h"
#include "models/curve_fit.h"
#include "models/distortion_function.h"
#include "models/monotone_cubic.h"
#include "models/theia_lens.h"

namespace ws {
namespace {

// Every row within 1e-9 of its real height, relatively.
void ExpectInterpolates(const Distortion& fit, const LensTable& table) {
  const DistortionFunction curve(fit);
  for (size_t i = 0; i < table.ideal.size(); ++i)
    EXPECT_LE(std::abs(curve.DistortedRadius(table.ideal[i]) - table.real[i]),
              1e-9 * table.real[i])
        << "row " << i << " r = " << table.ideal[i];
}

TEST(Collocation, InterpolatesEveryRowOfTheShippedTable) {
  const LensTable table = TheiaLikeLensTable();
  ASSERT_EQ(table.ideal.size(), 35u);
  const Distortion fit = FitBsplineByCollocation(table, 3);
  EXPECT_EQ(fit.kind, ModelKind::kBspline);
  EXPECT_EQ(fit.coeffs.size(), 35u);                   // square system (Eq. 9)
  EXPECT_EQ(fit.knots, SchoenbergWhitneyKnots(table.ideal, 3));  // knots of Eq. 8
  ExpectInterpolates(fit, table);
}

TEST(Collocation, InterpolatesAnyDegreeAndUnevenRowsNotStartingAtZero) {
  LensTable table;
  for (double r : {0.3, 0.35, 0.5, 0.8, 0.85, 1.3, 1.6, 2.2, 2.25, 2.9}) {
    table.ideal.push_back(r);
    table.real.push_back(r * (1 + 0.03 * std::sin(2 * r) - 0.01 * r * r));
  }
  for (int degree : {1, 2, 3, 5}) ExpectInterpolates(FitBsplineByCollocation(table, degree), table);
}

TEST(Collocation, UsesTheEvenLimitOfTheDistortionOnTheAxis) {
  LensTable table{{0, 0.1, 0.2, 0.4, 0.6}, {}};
  for (double r : table.ideal) table.real.push_back(r * (1 + 0.002 + 0.05 * r * r));
  const std::vector<double> distortion = TableDistortion(table);
  EXPECT_NEAR(distortion[0], 0.002, 1e-15);  // exact for D = c0 + c2 r^2
  EXPECT_NEAR(DistortionFunction(FitBsplineByCollocation(table, 3))(0.0), 0.002, 1e-12);
}

// A table generated from the model itself, over [0, 2.5] in normalized radius.
LensTable TableOf(const std::vector<double>& k) {
  LensTable table;
  for (int i = 0; i <= 30; ++i) {
    const double r = 2.5 * i / 30, r2 = r * r;
    double d = 0, power = 1;
    for (double ki : k) d += ki * (power *= r2);
    table.ideal.push_back(r);
    table.real.push_back(r * (1 + d));
  }
  return table;
}

void ExpectRecovers(ModelKind kind, const std::vector<double>& k) {
  const LensTable table = TableOf(k);
  const Distortion fit =
      FitByLeastSquares(MakeModel(Distortion{kind, 0, {}, {}}, Coefficients::kAll), table);
  ASSERT_EQ(fit.coeffs.size(), k.size());
  for (size_t i = 0; i < k.size(); ++i)
    EXPECT_NEAR(fit.coeffs[i], k[i], 1e-9 * (1 + std::abs(k[i]))) << kind << " k" << i + 1;
  const FitErrors errors = MeasureFitErrors(fit, table);
  EXPECT_LT(errors.max_abs, 1e-12) << kind;
}

TEST(PolynomialFit, RecoversPoly6FromItsOwnTable) { ExpectRecovers(ModelKind::kPoly6, {0.021, -0.0043, 0.00021}); }

TEST(PolynomialFit, RecoversPoly12FromItsOwnTable) {
  ExpectRecovers(ModelKind::kPoly12, {0.02, 0.013, -0.011, 0.0031, -4.2e-4, 2.1e-5});
}

TEST(PolynomialFit, FitsAnIdentifiableSplineToo) {
  const LensTable table = ScaleLensTable(TheiaLikeLensTable(), 1 / 1.3);
  const Distortion fit = FitByLeastSquares(MakeCalibrationModel(ModelKind::kBspline, {2.7, 8, 3}), table);
  EXPECT_EQ(fit.coeffs[0], 0.0);
  EXPECT_EQ(fit.coeffs[1], 0.0);
  EXPECT_LT(MeasureFitErrors(fit, table).max_abs, 2e-4);  // normalized radius: 0.26 um
}

TEST(FitErrors, MeasuresAtTheRowsAndBetweenThem) {
  const LensTable table{{0, 1, 2, 3}, {0, 1, 2, 3}};
  const Distortion constant{ModelKind::kPoly6, 0, {}, {0.01, 0, 0}};  // r' = r + 0.01 r^3
  const FitErrors errors = MeasureFitErrors(constant, table, 10);
  EXPECT_NEAR(errors.max_abs, 0.27, 1e-12);
  EXPECT_NEAR(errors.rms, std::sqrt((0.01 * 0.01 + 0.08 * 0.08 + 0.27 * 0.27) / 4), 1e-12);
  EXPECT_NEAR(errors.max_abs_between, 0.01 * 2.9 * 2.9 * 2.9, 1e-12);  // last sample before 3
}

TEST(MonotoneCubic, InterpolatesWithoutOvershoot) {
  const std::vector<double> x{0, 1, 2, 2.5, 4, 6}, y{0, 0.1, 0.1, 2, 2.1, 5};
  const MonotoneCubic f(x, y);
  for (size_t i = 0; i < x.size(); ++i) EXPECT_NEAR(f(x[i]), y[i], 1e-15);
  double previous = f(0);
  for (double t = 0.001; t <= 6; t += 0.001) {
    const double value = f(t);
    EXPECT_GE(value, previous - 1e-15) << t;
    previous = value;
  }
  EXPECT_NEAR(f(1.5), 0.1, 1e-15);  // flat data stays flat
  EXPECT_NEAR(MonotoneCubic({0, 2}, {1, 3})(0.5), 1.5, 1e-15);
  EXPECT_THROW(MonotoneCubic({0, 0}, {1, 2}), std::invalid_argument);
}

}  // namespace
}  // namespace ws
