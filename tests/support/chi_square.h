#pragma once
// Chi-square goodness-of-fit tests for samplers (after Mitsuba's chi2 test and pbrt's BSDF tests):
// compare observed counts per bin with the counts a density predicts, and report a p-value.
//
// Typical use for a direction sampler:
//   SphereHistogram h(10, 20);
//   for (...) sampled ? h.add(local) : h.addFailure();
//   ChiSquareResult r = h.test([&](const Vec3& w) { return pdf(w); });
//   EXPECT_TRUE(r.passes(0.01)) << r.describe();
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "core/math.h"

namespace relt::test {

// Regularised lower / upper incomplete gamma functions P(a, x) and Q(a, x) = 1 - P(a, x), a > 0,
// x >= 0 (series for x < a + 1, Lentz continued fraction otherwise).
double regularizedGammaP(double a, double x);
double regularizedGammaQ(double a, double x);
// Upper tail probability of the chi-square distribution with dof degrees of freedom.
double chiSquareSurvival(double statistic, double dof);

struct ChiSquareResult {
  double statistic = 0.0;
  int degreesOfFreedom = 0;
  double pValue = 0.0;
  int pooledBins = 0;  // bins merged into the pooled cell
  // The cell contributing most to the statistic (input index; -1 = the pooled cell), for diagnostics.
  int worstCell = -1;
  double worstObserved = 0.0, worstExpected = 0.0;
  std::string error;  // set when the data cannot fit at all (counts where nothing is expected)
  bool passes(double significance) const { return error.empty() && pValue > significance; }
  std::string describe() const;
};

// Pearson's test of observed against expected counts (same length; the expected counts must sum to
// the number of draws, or the caller must add a remainder cell). Bins with expectation below
// minExpected are pooled, in increasing order of expectation, into one cell that keeps absorbing
// bins until its own expectation reaches minExpected (Mitsuba's rule). dof = cells - 1.
ChiSquareResult chiSquareTest(std::span<const double> observed, std::span<const double> expected,
                              double minExpected = 5.0);

// Error control of integrateSphereRegion: a rectangle is accepted when its 3 x 3 Gauss estimate and
// the sum over its four halves differ by at most max(absolute, relative * |value|).
struct QuadratureTolerance {
  double absolute = 1e-9;
  double relative = 1e-5;
  int initialSplits = 3;  // the region is first cut into initialSplits^2 rectangles
  int maxDepth = 10;
};

// Integral of fn(w) over the region [theta0, theta1] x [phi0, phi1] of the unit sphere (theta from
// +z, phi from +x; the sin(theta) Jacobian is included), by adaptive 3 x 3 Gauss-Legendre cubature.
// fn takes a unit vector; it is never evaluated on the region's boundary, so discontinuities there
// (the horizon) cost nothing. Narrow peaks are found as long as the initial grid touches them.
double integrateSphereRegion(const std::function<double(const Vec3&)>& fn, double theta0, double theta1, double phi0,
                             double phi1, const QuadratureTolerance& tol = {});

// Histogram of unit directions in thetaBins x phiBins equal-angle bins, plus a count of failed draws
// (a sampler that may return nothing: its density then integrates to less than one).
class SphereHistogram {
 public:
  SphereHistogram(int thetaBins, int phiBins);

  void add(const Vec3& w);
  void addFailure() { ++failures_; }
  int binOf(const Vec3& w) const;
  double draws() const { return draws_ + failures_; }
  double failures() const { return failures_; }
  const std::vector<double>& counts() const { return counts_; }

  // Expected counts for draws() draws from the solid-angle density pdf (integrated over each bin
  // with integrateSphereRegion), followed by the expected number of failures.
  std::vector<double> expectedCounts(const std::function<double(const Vec3&)>& pdf,
                                     const QuadratureTolerance& tol = {}) const;
  // Chi-square test of the histogram (bins + failure cell) against pdf.
  ChiSquareResult test(const std::function<double(const Vec3&)>& pdf, double minExpected = 5.0) const;
  // The same with precomputed expectedCounts().
  ChiSquareResult test(const std::vector<double>& expected, double minExpected = 5.0) const;

 private:
  int thetaBins_, phiBins_;
  std::vector<double> counts_;
  double draws_ = 0.0, failures_ = 0.0;
};

}  // namespace relt::test
