#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>

#include "models/bspline_basis.h"
#include "models/bspline_distortion.h"

namespace ws {
namespace {

// N_{i,K}(r) straight from the de Boor-Cox definition (paper Eqs. 4-5).
double DeBoorCox(const std::vector<double>& t, int i, int k, double r) {
  if (k == 0) return t[i] <= r && r < t[i + 1] ? 1.0 : 0.0;
  double value = 0;
  if (t[i + k] > t[i]) value += (r - t[i]) / (t[i + k] - t[i]) * DeBoorCox(t, i, k - 1, r);
  if (t[i + k + 1] > t[i + 1])
    value += (t[i + k + 1] - r) / (t[i + k + 1] - t[i + 1]) * DeBoorCox(t, i + 1, k - 1, r);
  return value;
}

struct KnotCase {
  std::vector<double> knots;
  int degree;
};

std::vector<KnotCase> KnotCases() {
  std::vector<KnotCase> cases;
  for (int degree = 1; degree <= 5; ++degree)
    cases.push_back({UniformClampedKnots(2.0, 7, degree), degree});
  cases.push_back({SchoenbergWhitneyKnots({0, 0.1, 0.15, 0.5, 0.9, 1.0, 1.7, 2.0, 2.05}, 3), 3});
  cases.push_back({{0, 0, 0, 0, 1, 1, 2, 3, 3, 3, 3}, 3});  // a double interior knot
  return cases;
}

TEST(BsplineBasis, NonNegativeAndSumsToOneOnTheDomain) {
  for (const KnotCase& c : KnotCases()) {
    const int n = NumBasisFunctions(c.knots, c.degree);
    const double a = c.knots[c.degree], b = c.knots[n];
    for (int s = 0; s <= 1000; ++s) {
      const double r = a + (b - a) * s / 1000;
      const std::vector<double> basis = EvaluateBasis(c.knots, c.degree, r);
      ASSERT_EQ(static_cast<int>(basis.size()), n);
      for (double value : basis) EXPECT_GE(value, 0.0) << "degree " << c.degree << " r " << r;
      EXPECT_NEAR(std::accumulate(basis.begin(), basis.end(), 0.0), 1.0, 1e-14)
          << "degree " << c.degree << " r " << r;
    }
  }
}

TEST(BsplineBasis, MatchesTheDeBoorCoxDefinition) {
  for (const KnotCase& c : KnotCases()) {
    const int n = NumBasisFunctions(c.knots, c.degree);
    const double a = c.knots[c.degree], b = c.knots[n];
    for (int s = 0; s < 500; ++s) {  // the half-open definition leaves r = b out
      const double r = a + (b - a) * s / 500;
      const std::vector<double> basis = EvaluateBasis(c.knots, c.degree, r);
      for (int i = 0; i < n; ++i)
        EXPECT_NEAR(basis[i], DeBoorCox(c.knots, i, c.degree, r), 1e-14)
            << "N_" << i << "," << c.degree << "(" << r << ")";
    }
  }
}

TEST(BsplineBasis, SlopesAreTheDerivativesOfTheSpansPolynomials) {
  for (const KnotCase& c : KnotCases()) {
    const int n = NumBasisFunctions(c.knots, c.degree);
    const double a = c.knots[c.degree], b = c.knots[n], h = 1e-6;
    for (int s = 1; s < 100; ++s) {
      const double r = a + (b - a) * s / 100;
      const int span = FindSpan(c.knots, c.degree, r);
      double values[kMaxSplineDegree + 1], slopes[kMaxSplineDegree + 1];
      double plain[kMaxSplineDegree + 1], above[kMaxSplineDegree + 1], below[kMaxSplineDegree + 1];
      NonZeroBasisWithSlopes(c.knots, c.degree, span, r, values, slopes);
      NonZeroBasis(c.knots, c.degree, span, r, plain);
      NonZeroBasis(c.knots, c.degree, span, r + h, above);  // the same span's polynomial
      NonZeroBasis(c.knots, c.degree, span, r - h, below);
      for (int j = 0; j <= c.degree; ++j) {
        EXPECT_NEAR(values[j], plain[j], 1e-15);  // the dual number's division rounds apart
        const double central = (above[j] - below[j]) / (2 * h);
        EXPECT_NEAR(slopes[j], central, 1e-6 * (1 + std::abs(central)))
            << "N'_" << span - c.degree + j << "," << c.degree << "(" << r << ")";
      }
    }
  }
}

TEST(BsplineBasis, MatchesTheClosedFormForUniformCubicKnots) {
  std::vector<double> knots(11);
  std::iota(knots.begin(), knots.end(), 0.0);  // 0, 1, ..., 10: n = 7, domain [3, 7]
  for (double r = 3.0; r < 7.0; r += 0.01) {
    const int span = static_cast<int>(std::floor(r));
    const double u = r - span;
    const double expected[4] = {(1 - u) * (1 - u) * (1 - u) / 6,
                                (3 * u * u * u - 6 * u * u + 4) / 6,
                                (-3 * u * u * u + 3 * u * u + 3 * u + 1) / 6, u * u * u / 6};
    const std::vector<double> basis = EvaluateBasis(knots, 3, r);
    for (int i = 0; i < 7; ++i) {
      const int j = i - (span - 3);
      EXPECT_NEAR(basis[i], j >= 0 && j <= 3 ? expected[j] : 0.0, 1e-14) << "i " << i << " r " << r;
    }
  }
}

TEST(BsplineBasis, FindsSpansAndClampsOutsideTheDomain) {
  const std::vector<double> knots = UniformClampedKnots(2.0, 4, 3);  // 0 0 0 0 .5 1 1.5 2 2 2 2
  EXPECT_EQ(FindSpan(knots, 3, 0.0), 3);
  EXPECT_EQ(FindSpan(knots, 3, 0.5), 4);
  EXPECT_EQ(FindSpan(knots, 3, 1.49), 5);
  EXPECT_EQ(FindSpan(knots, 3, 2.0), 6);
  EXPECT_EQ(FindSpan(knots, 3, 7.0), 6);
  EXPECT_EQ(FindSpan(knots, 3, -1.0), 3);
  const std::vector<double> doubled{0, 0, 0, 0, 1, 1, 2, 3, 3, 3, 3};
  EXPECT_EQ(FindSpan(doubled, 3, 1.0), 5);  // [1, 2): the empty span [1, 1) is skipped
}

TEST(BsplineBasis, SchoenbergWhitneyKnotsFollowEquation8) {
  const std::vector<double> sites{0, 0.1, 0.15, 0.5, 0.9, 1.0, 1.7, 2.0, 2.05};
  const int degree = 3;
  const std::vector<double> t = SchoenbergWhitneyKnots(sites, degree);
  ASSERT_EQ(t.size(), sites.size() + degree + 1);
  for (int i = 0; i <= degree; ++i) {
    EXPECT_EQ(t[i], sites.front());
    EXPECT_EQ(t[t.size() - 1 - i], sites.back());
  }
  EXPECT_DOUBLE_EQ(t[4], (0.1 + 0.15 + 0.5) / 3);
  for (size_t i = 1; i + 1 < sites.size(); ++i) {  // t_i < r_i < t_{i+K+1}
    EXPECT_LT(t[i], sites[i]);
    EXPECT_LT(sites[i], t[i + degree + 1]);
  }
  EXPECT_THROW(SchoenbergWhitneyKnots({0, 1, 2}, 3), std::invalid_argument);
  EXPECT_THROW(SchoenbergWhitneyKnots({0, 1, 1, 2, 3}, 3), std::invalid_argument);
}

TEST(BsplineBasis, UniformClampedKnotsCoverZeroToRmax) {
  EXPECT_EQ(UniformClampedKnots(2.0, 4, 3),
            (std::vector<double>{0, 0, 0, 0, 0.5, 1, 1.5, 2, 2, 2, 2}));
  EXPECT_EQ(NumBasisFunctions(UniformClampedKnots(2.0, 8, 3), 3), 11);
  EXPECT_THROW(UniformClampedKnots(0.0, 4, 3), std::invalid_argument);
  EXPECT_THROW(UniformClampedKnots(1.0, 0, 3), std::invalid_argument);
}

TEST(BsplineBasis, RejectsBadKnotVectors) {
  EXPECT_THROW(ValidateKnots({0, 0, 1, 1}, 0), std::invalid_argument);
  EXPECT_THROW(ValidateKnots({0, 0, 0, 1, 1, 1}, 3), std::invalid_argument);
  EXPECT_THROW(ValidateKnots({0, 0, 0, 0, 2, 1, 3, 3, 3, 3}, 3), std::invalid_argument);
  EXPECT_THROW(ValidateKnots({0, 0, 0, 0, 0, 0, 0, 0}, 3), std::invalid_argument);
  EXPECT_THROW(ValidateKnots({0, 0, 0, 0, NAN, 3, 3, 3, 3}, 3), std::invalid_argument);
  EXPECT_NO_THROW(ValidateKnots(UniformClampedKnots(1.0, 3, 3), 3));
}

// B-splines reproduce polynomials of their degree: interpolating a cubic
// gives that cubic, also beyond the end knots where the end pieces continue.
TEST(BsplineDistortion, ReproducesACubicAndExtrapolatesItsEndPieces) {
  auto cubic = [](double r) { return 0.1 + 0.3 * r - 0.2 * r * r + 0.05 * r * r * r; };
  const std::vector<double> sites{0, 0.2, 0.5, 0.7, 1.1, 1.4, 1.8, 2.0};
  const std::vector<double> knots = SchoenbergWhitneyKnots(sites, 3);
  const int n = NumBasisFunctions(knots, 3);
  // Solve the collocation system by Gaussian elimination (small and well-posed).
  std::vector<std::vector<double>> a;
  for (double r : sites) {
    a.push_back(EvaluateBasis(knots, 3, r));
    a.back().push_back(cubic(r));
  }
  for (int col = 0; col < n; ++col) {
    int pivot = col;
    for (int row = col; row < n; ++row)
      if (std::abs(a[row][col]) > std::abs(a[pivot][col])) pivot = row;
    std::swap(a[col], a[pivot]);
    for (int row = 0; row < n; ++row) {
      if (row == col) continue;
      const double factor = a[row][col] / a[col][col];
      for (int k = col; k <= n; ++k) a[row][k] -= factor * a[col][k];
    }
  }
  std::vector<double> alpha(n);
  for (int i = 0; i < n; ++i) alpha[i] = a[i][n] / a[i][i];
  const BsplineDistortion spline(knots, 3, Coefficients::kAll);
  for (double r : {0.0, 0.33, 1.0, 1.99, 2.0, 2.5, 3.7, -0.4})
    EXPECT_NEAR(spline.RadialDistortion(alpha.data(), r), cubic(r), 1e-12) << "r " << r;
}

TEST(BsplineDistortion, IdentifiableSplineIsZeroAndFlatOnTheAxis) {
  using Jet = ceres::Jet<double, 1>;
  const BsplineDistortion spline = BsplineDistortion::ForCalibration({2.5, 6, 3});
  ASSERT_EQ(spline.NumBasis(), 9);
  ASSERT_EQ(spline.NumCoeffs(), 7);
  EXPECT_EQ(spline.CoeffName(0), "alpha2");
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-0.2, 0.2);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Jet> coeffs;
    for (int i = 0; i < spline.NumCoeffs(); ++i) coeffs.emplace_back(uniform(random));
    const Jet b = spline.RadialDistortion(coeffs.data(), Jet(0.0, 0));
    EXPECT_EQ(b.a, 0.0);
    EXPECT_EQ(b.v[0], 0.0);
    // and it is not flat further out
    EXPECT_NE(spline.RadialDistortion(coeffs.data(), Jet(0.3, 0)).v[0], 0.0);
  }
}

TEST(BsplineDistortion, FreeSplineStartsAtAlpha0WithTheClampedSlope) {
  using Jet = ceres::Jet<double, 1>;
  const std::vector<double> knots = UniformClampedKnots(2.0, 5, 3);
  const BsplineDistortion spline(knots, 3, Coefficients::kAll);
  std::vector<Jet> alpha;
  for (int i = 0; i < spline.NumCoeffs(); ++i) alpha.emplace_back(0.01 * (i + 1) * (i % 2 ? -1 : 1));
  const Jet b = spline.RadialDistortion(alpha.data(), Jet(0.0, 0));
  EXPECT_DOUBLE_EQ(b.a, alpha[0].a);
  EXPECT_DOUBLE_EQ(b.v[0], 3 * (alpha[1].a - alpha[0].a) / knots[4]);  // K (a1 - a0) / t_{K+1}
}

TEST(BsplineDistortion, StoresAllAlphasAndRestoresTheEstimatedOnes) {
  const BsplineDistortion spline = BsplineDistortion::ForCalibration({2.0, 4, 3});
  const std::vector<double> estimated{0.01, 0.02, -0.01, 0.03, 0.0};
  const Distortion stored = spline.ToData(estimated.data());
  EXPECT_EQ(stored.kind, ModelKind::kBspline);
  EXPECT_EQ(stored.degree, 3);
  EXPECT_EQ(stored.knots, spline.knots());
  EXPECT_EQ(stored.coeffs, (std::vector<double>{0, 0, 0.01, 0.02, -0.01, 0.03, 0.0}));
  EXPECT_EQ(spline.EstimatedCoeffs(stored.coeffs), estimated);
  std::vector<double> ungauged = stored.coeffs;
  ungauged[1] = 1e-3;
  EXPECT_THROW(spline.EstimatedCoeffs(ungauged), std::invalid_argument);
  EXPECT_THROW(spline.EstimatedCoeffs({0, 0, 1}), std::invalid_argument);
  // Identifiable needs knots clamped at zero.
  EXPECT_THROW(BsplineDistortion({1, 1, 1, 1, 2, 2, 2, 2}, 3, Coefficients::kIdentifiable),
               std::invalid_argument);
}

}  // namespace
}  // namespace ws
