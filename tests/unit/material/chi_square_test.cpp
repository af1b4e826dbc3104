// The chi-square helper of tests/support (used by the BSDF tests here and later by the Markov chain
// and exchange tests): incomplete gamma function, pooling, and its power to reject.
#include "chi_square.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/rng.h"
#include "core/sampling.h"

using namespace relt;
using namespace relt::test;

namespace {

TEST(ChiSquare, IncompleteGammaMatchesClosedForms) {
  for (double x : {0.01, 0.5, 1.0, 3.0, 10.0, 40.0}) {
    EXPECT_NEAR(regularizedGammaQ(1.0, x), std::exp(-x), 1e-12) << x;  // Q(1, x) = e^-x
    EXPECT_NEAR(regularizedGammaP(0.5, x), std::erf(std::sqrt(x)), 1e-12) << x;
    for (double a : {0.5, 2.0, 7.5, 50.0}) EXPECT_NEAR(regularizedGammaP(a, x) + regularizedGammaQ(a, x), 1.0, 1e-12);
  }
  EXPECT_EQ(regularizedGammaP(3.0, 0.0), 0.0);
  EXPECT_EQ(regularizedGammaQ(3.0, 0.0), 1.0);
}

TEST(ChiSquare, SurvivalFunctionMatchesTables) {
  // Critical values at 5%: 3.841 (1 dof), 18.307 (10 dof), 124.342 (100 dof).
  EXPECT_NEAR(chiSquareSurvival(3.841459, 1), 0.05, 1e-6);
  EXPECT_NEAR(chiSquareSurvival(18.307038, 10), 0.05, 1e-6);
  EXPECT_NEAR(chiSquareSurvival(124.342113, 100), 0.05, 1e-6);
  EXPECT_NEAR(chiSquareSurvival(2.0 * std::log(2.0), 2), 0.5, 1e-12);  // 2 dof: exp(-x / 2)
}

TEST(ChiSquare, PerfectFitHasPValueOne) {
  const std::vector<double> counts = {10, 20, 30, 40};
  const ChiSquareResult r = chiSquareTest(counts, counts);
  EXPECT_EQ(r.statistic, 0.0);
  EXPECT_EQ(r.degreesOfFreedom, 3);
  EXPECT_NEAR(r.pValue, 1.0, 1e-12);
}

TEST(ChiSquare, PoolsBinsWithSmallExpectation) {
  // Three bins expecting 1, 2 and 3 pool into one cell expecting 6; the other two stay.
  const std::vector<double> observed = {2, 1, 3, 50, 44}, expected = {1, 2, 3, 50, 44};
  const ChiSquareResult r = chiSquareTest(observed, expected);
  EXPECT_EQ(r.pooledBins, 3);
  EXPECT_EQ(r.degreesOfFreedom, 2);
  EXPECT_EQ(r.statistic, 0.0);
}

TEST(ChiSquare, ObservationsWhereNoneAreExpectedFail) {
  const std::vector<double> observed = {10, 1}, expected = {11, 0};
  const ChiSquareResult r = chiSquareTest(observed, expected);
  EXPECT_FALSE(r.passes(0.01));
  EXPECT_FALSE(r.error.empty());
}

TEST(ChiSquare, SphereHistogramAcceptsTheRightDensityAndRejectsAWrongOne) {
  SphereHistogram h(10, 20);
  Rng rng(1);
  for (int i = 0; i < 200000; ++i) {
    const Vec3 w = uniformSphere(Vec2(rng.uniform(), rng.uniform()));
    if (w.z < -0.9f)
      h.addFailure();  // a sampler that sometimes fails: its density integrates to less than one
    else
      h.add(w);
  }
  EXPECT_NEAR(h.failures() / h.draws(), 0.05, 0.005);
  const ChiSquareResult right = h.test([](const Vec3& w) { return w.z < -0.9f ? 0.0 : double(kInv4Pi); });
  EXPECT_TRUE(right.passes(0.01)) << right.describe();
  // A density 5% off in each hemisphere (still normalised) is detected.
  const ChiSquareResult wrong =
      h.test([](const Vec3& w) { return w.z < -0.9f ? 0.0 : double(kInv4Pi) * (w.z > 0.0f ? 1.05 : 0.95); });
  EXPECT_LT(wrong.pValue, 1e-6) << wrong.describe();
}

TEST(ChiSquare, AdaptiveCubatureFindsNarrowPeaks) {
  // A normalised von Mises-Fisher lobe of width 0.03 rad around a direction off any node line.
  // (Narrower lobes run into the float precision of the Vec3 directions, not into the cubature.)
  const Vec3 mu = glm::normalize(Vec3(0.3f, 0.2f, -0.9f));
  const double kappa = 1e3;
  auto lobe = [&](const Vec3& w) {
    return kappa / (2 * M_PI * (1 - std::exp(-2 * kappa))) * std::exp(kappa * (glm::dot(w, mu) - 1.0));
  };
  double sum = 0.0;
  for (int t = 0; t < 10; ++t)
    for (int p = 0; p < 20; ++p)
      sum += integrateSphereRegion(lobe, M_PI * t / 10, M_PI * (t + 1) / 10, M_PI * p / 10, M_PI * (p + 1) / 10);
  EXPECT_NEAR(sum, 1.0, 1e-4);
}

}  // namespace
