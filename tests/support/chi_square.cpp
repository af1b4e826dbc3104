#include "chi_square.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>

namespace relt::test {

namespace {
constexpr double kEps = 1e-15;
constexpr double kTiny = 1e-300;
constexpr int kMaxIterations = 100000;

// x^a e^-x / Gamma(a), the common prefactor of both expansions.
double gammaPrefactor(double a, double x) { return std::exp(a * std::log(x) - x - std::lgamma(a)); }

// P(a, x) = x^a e^-x / Gamma(a) * sum_n x^n / (a (a+1) ... (a+n)); converges fast for x < a + 1.
double gammaPSeries(double a, double x) {
  double term = 1.0 / a, sum = term;
  for (int n = 1; n < kMaxIterations; ++n) {
    term *= x / (a + n);
    sum += term;
    if (std::abs(term) < std::abs(sum) * kEps) break;
  }
  return sum * gammaPrefactor(a, x);
}

// Q(a, x) by its continued fraction 1/(x+1-a- 1(1-a)/(x+3-a- 2(2-a)/(x+5-a- ...))), evaluated with
// the modified Lentz method; converges fast for x >= a + 1.
double gammaQContinuedFraction(double a, double x) {
  double b = x + 1.0 - a;
  double c = 1.0 / kTiny;
  double d = 1.0 / b;
  double h = d;
  for (int i = 1; i < kMaxIterations; ++i) {
    const double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < kTiny) d = kTiny;
    c = b + an / c;
    if (std::abs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    const double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1.0) < kEps) break;
  }
  return h * gammaPrefactor(a, x);
}
}  // namespace

double regularizedGammaP(double a, double x) {
  if (x <= 0.0) return 0.0;
  if (std::isinf(x)) return 1.0;
  return x < a + 1.0 ? gammaPSeries(a, x) : 1.0 - gammaQContinuedFraction(a, x);
}

double regularizedGammaQ(double a, double x) {
  if (x <= 0.0) return 1.0;
  if (std::isinf(x)) return 0.0;
  return x < a + 1.0 ? 1.0 - gammaPSeries(a, x) : gammaQContinuedFraction(a, x);
}

double chiSquareSurvival(double statistic, double dof) {
  if (dof <= 0.0) return 1.0;
  return regularizedGammaQ(0.5 * dof, 0.5 * statistic);
}

std::string ChiSquareResult::describe() const {
  std::ostringstream s;
  s << "chi2 = " << statistic << ", dof = " << degreesOfFreedom << ", p = " << pValue
    << ", pooled bins = " << pooledBins << ", worst cell " << worstCell << " (observed " << worstObserved
    << ", expected " << worstExpected << ")";
  if (!error.empty()) s << "; " << error;
  return s.str();
}

ChiSquareResult chiSquareTest(std::span<const double> observed, std::span<const double> expected, double minExpected) {
  ChiSquareResult r;
  if (observed.size() != expected.size()) {
    r.error = "observed and expected differ in length";
    return r;
  }
  std::vector<size_t> order(expected.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return expected[a] < expected[b]; });

  double worst = -1.0;
  auto addCell = [&](double obs, double exp, int index) {
    const double term = (obs - exp) * (obs - exp) / exp;
    r.statistic += term;
    ++r.degreesOfFreedom;
    if (term > worst) {
      worst = term;
      r.worstCell = index;
      r.worstObserved = obs;
      r.worstExpected = exp;
    }
  };
  double pooledObserved = 0.0, pooledExpected = 0.0;
  for (size_t i : order) {
    const double e = std::max(0.0, expected[i]), o = observed[i];
    if (e == 0.0) {
      if (o > 0.0) {
        std::ostringstream s;
        s << "bin " << i << " has " << o << " observations where none are expected";
        r.error = s.str();
        r.worstCell = static_cast<int>(i);
        r.worstObserved = o;
        r.worstExpected = 0.0;
        return r;
      }
      continue;  // empty and impossible: carries no information
    }
    if (e < minExpected || (pooledExpected > 0.0 && pooledExpected < minExpected)) {
      pooledObserved += o;
      pooledExpected += e;
      ++r.pooledBins;
    } else {
      addCell(o, e, static_cast<int>(i));
    }
  }
  if (pooledExpected > 0.0) addCell(pooledObserved, pooledExpected, -1);
  // One constraint: the counts sum to the number of draws.
  r.degreesOfFreedom -= 1;
  r.pValue = chiSquareSurvival(r.statistic, r.degreesOfFreedom);
  return r;
}

namespace {
constexpr double kGaussNode[3] = {-0.7745966692414834, 0.0, 0.7745966692414834};
constexpr double kGaussWeight[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};

// 3 x 3 Gauss-Legendre estimate of the integral of fn(w) sin(theta) over one (theta, phi) rectangle.
// Its nodes avoid the rectangle's edges, where densities are often discontinuous (the horizon is a
// bin edge).
double gaussRectangle(const std::function<double(const Vec3&)>& fn, double t0, double t1, double p0, double p1) {
  const double ht = 0.5 * (t1 - t0), hp = 0.5 * (p1 - p0);
  double sum = 0.0;
  for (int a = 0; a < 3; ++a) {
    const double theta = t0 + ht * (1.0 + kGaussNode[a]);
    const double sinT = std::sin(theta), cosT = std::cos(theta);
    double row = 0.0;
    for (int b = 0; b < 3; ++b) {
      const double phi = p0 + hp * (1.0 + kGaussNode[b]);
      row += kGaussWeight[b] * fn(Vec3(float(sinT * std::cos(phi)), float(sinT * std::sin(phi)), float(cosT)));
    }
    sum += kGaussWeight[a] * sinT * row;
  }
  return sum * ht * hp;
}

double adaptiveRectangle(const std::function<double(const Vec3&)>& fn, double t0, double t1, double p0, double p1,
                         double estimate, const QuadratureTolerance& tol, int depth) {
  const double tm = 0.5 * (t0 + t1), pm = 0.5 * (p0 + p1);
  const double c[4] = {gaussRectangle(fn, t0, tm, p0, pm), gaussRectangle(fn, tm, t1, p0, pm),
                       gaussRectangle(fn, t0, tm, pm, p1), gaussRectangle(fn, tm, t1, pm, p1)};
  const double refined = c[0] + c[1] + c[2] + c[3];
  if (depth >= tol.maxDepth || std::abs(refined - estimate) <= std::max(tol.absolute, tol.relative * std::abs(refined)))
    return refined;
  return adaptiveRectangle(fn, t0, tm, p0, pm, c[0], tol, depth + 1) +
         adaptiveRectangle(fn, tm, t1, p0, pm, c[1], tol, depth + 1) +
         adaptiveRectangle(fn, t0, tm, pm, p1, c[2], tol, depth + 1) +
         adaptiveRectangle(fn, tm, t1, pm, p1, c[3], tol, depth + 1);
}
}  // namespace

double integrateSphereRegion(const std::function<double(const Vec3&)>& fn, double theta0, double theta1, double phi0,
                             double phi1, const QuadratureTolerance& tol) {
  // Start from a fixed grid so that narrow peaks are not missed altogether, then refine.
  const int n = std::max(1, tol.initialSplits);
  const double ht = (theta1 - theta0) / n, hp = (phi1 - phi0) / n;
  double sum = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double t0 = theta0 + i * ht, p0 = phi0 + j * hp;
      sum += adaptiveRectangle(fn, t0, t0 + ht, p0, p0 + hp, gaussRectangle(fn, t0, t0 + ht, p0, p0 + hp), tol, 0);
    }
  return sum;
}

SphereHistogram::SphereHistogram(int thetaBins, int phiBins)
    : thetaBins_(thetaBins), phiBins_(phiBins), counts_(size_t(thetaBins) * phiBins, 0.0) {}

int SphereHistogram::binOf(const Vec3& w) const {
  const double theta = std::acos(std::clamp(double(w.z), -1.0, 1.0));
  double phi = std::atan2(double(w.y), double(w.x));
  if (phi < 0.0) phi += 2.0 * M_PI;
  const int t = std::clamp(int(theta / M_PI * thetaBins_), 0, thetaBins_ - 1);
  const int p = std::clamp(int(phi / (2.0 * M_PI) * phiBins_), 0, phiBins_ - 1);
  return t * phiBins_ + p;
}

void SphereHistogram::add(const Vec3& w) {
  counts_[binOf(w)] += 1.0;
  draws_ += 1.0;
}

std::vector<double> SphereHistogram::expectedCounts(const std::function<double(const Vec3&)>& pdf,
                                                    const QuadratureTolerance& tol) const {
  std::vector<double> expected(counts_.size() + 1, 0.0);
  const double n = draws();
  double total = 0.0;
  for (int t = 0; t < thetaBins_; ++t)
    for (int p = 0; p < phiBins_; ++p) {
      const double e = n * integrateSphereRegion(pdf, M_PI * t / thetaBins_, M_PI * (t + 1) / thetaBins_,
                                                 2.0 * M_PI * p / phiBins_, 2.0 * M_PI * (p + 1) / phiBins_, tol);
      expected[size_t(t) * phiBins_ + p] = e;
      total += e;
    }
  expected.back() = std::max(0.0, n - total);
  return expected;
}

ChiSquareResult SphereHistogram::test(const std::function<double(const Vec3&)>& pdf, double minExpected) const {
  return test(expectedCounts(pdf), minExpected);
}

ChiSquareResult SphereHistogram::test(const std::vector<double>& expected, double minExpected) const {
  std::vector<double> observed = counts_;
  observed.push_back(failures_);
  return chiSquareTest(observed, expected, minExpected);
}

}  // namespace relt::test
