// BDPT's MIS weights, computed incrementally from the subpaths' stored densities, against a
// brute-force recomputation of every strategy's density from the full path's geometry
// (Veach 1997 §10.2; thesis digest §1.6). Equal weights for every strategy of random paths mean
// the weights of all strategies that can make a path sum to 1. The tolerance covers float
// round-off in the renderer's incremental ratio walk.
#include <gtest/gtest.h>

#include <cmath>

#include "path/bdpt.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"
#include "render_fixture.h"
#include "test_support.h"

using namespace relt;

namespace {

struct Record {
  std::vector<PathVertex> path;  // x_0 (light end) .. x_{n-1} (camera)
  int s = 0;
  float weight = 0.0f;
};

Vec3 dirTo(const PathVertex& from, const PathVertex& to) { return glm::normalize(to.sp.p - from.sp.p); }

// Solid angle to area, recomputed here rather than taken from the renderer.
double toArea(double pdfW, const PathVertex& from, const PathVertex& to) {
  const Vec3 d = to.sp.p - from.sp.p;
  const double dist2 = glm::dot(d, d);
  double pdf = pdfW / dist2;
  const bool hasNormal = to.type == PathVertex::Type::Surface || (to.type == PathVertex::Type::Light && !to.delta);
  if (hasNormal) pdf *= std::abs(glm::dot(to.sp.ng, d)) / std::sqrt(dist2);
  return pdf;
}

double continuation(const PathVertex& v, bool roulette) {
  return roulette ? continuationProbability(v.bsdf->material()) : 1.0;
}

// Brute force: the density of every strategy s' for the full path, then the heuristic.
double bruteForceWeight(const Renderer& r, const Record& rec, MisHeuristic h, bool roulette) {
  const PathContext& ctx = r.context();
  const std::vector<PathVertex>& x = rec.path;
  const int n = static_cast<int>(x.size());
  std::vector<double> fromLight(n), fromCamera(n);
  // From the light end: pick x position, then the emission direction, then BSDF sampling.
  const uint32_t light =
      x[0].type == PathVertex::Type::Light ? x[0].light : ctx.lights.lightOfTriangle(x[0].sp.triangle);
  fromLight[0] = ctx.lights.pdfPick(light) * ctx.lights.pdfPosition(light);
  if (n > 1) fromLight[1] = toArea(ctx.lights.pdfDirection(light, x[0].sp, dirTo(x[0], x[1])), x[0], x[1]);
  for (int i = 2; i < n; ++i) {
    const PathVertex& v = x[i - 1];
    fromLight[i] = toArea(v.bsdf->pdf(dirTo(v, x[i - 2]), dirTo(v, x[i])) * continuation(v, roulette), v, x[i]);
  }
  // From the camera end.
  fromCamera[n - 1] = 1.0;
  fromCamera[n - 2] = toArea(ctx.camera.pdfDirection(dirTo(x[n - 1], x[n - 2])), x[n - 1], x[n - 2]);
  for (int i = n - 3; i >= 0; --i) {
    const PathVertex& v = x[i + 1];
    fromCamera[i] = toArea(v.bsdf->pdf(dirTo(v, x[i + 2]), dirTo(v, x[i])) * continuation(v, roulette), v, x[i]);
  }
  auto isDelta = [&](int i) { return x[i].type == PathVertex::Type::Surface && x[i].bsdf->isDelta(); };
  const bool deltaLight = x[0].type == PathVertex::Type::Light && x[0].delta;
  auto remap = [](double p) { return p != 0.0 ? p : 1.0; };
  auto valid = [&](int s) {
    if (s == n) return false;                    // t = 0: the pinhole cannot be hit
    if (n == 2 && s == 1) return false;          // (1,1) is not used
    if (s == 0) return !deltaLight && !isDelta(0);
    return !isDelta(s - 1) && !isDelta(s);
  };
  auto density = [&](int s) {
    double p = 1.0;
    for (int i = 0; i < s; ++i) p *= remap(fromLight[i]);
    for (int i = s; i < n; ++i) p *= remap(fromCamera[i]);
    return p;
  };
  const double beta = misExponent(h);
  double sum = 0.0;
  for (int s = 0; s <= n; ++s)
    if (valid(s)) sum += std::pow(density(s), beta);
  return std::pow(density(rec.s), beta) / sum;
}

void checkScene(const std::string& name, MisHeuristic heuristic, bool roulette = true) {
  RenderSettings settings;
  settings.width = settings.height = 32;
  settings.heuristic = heuristic;
  Renderer renderer(loadGltf(test::sourcePath("scenes/" + name + ".gltf")), settings);
  Bdpt bdpt(renderer.context(), roulette);
  std::vector<Record> records;
  bdpt.setObserver([&](std::span<const PathVertex> light, std::span<const PathVertex> camera, float w, const Color&) {
    Record rec;
    rec.s = static_cast<int>(light.size());
    rec.path.assign(light.begin(), light.end());
    for (auto it = camera.rbegin(); it != camera.rend(); ++it) rec.path.push_back(*it);
    rec.weight = w;
    records.push_back(std::move(rec));
  });
  PathSample sample;
  for (uint64_t i = 0; i < 4000 && records.size() < 20000; ++i) {
    IndependentSource source(hashKey(99, i));
    bdpt.trace(Vec2(source.next(SampleStream::Camera) * 32, source.next(SampleStream::Camera) * 32), source, sample);
    sample.clear();
  }
  ASSERT_GT(records.size(), 1000u) << name;
  int withDelta = 0, checked = 0;
  for (const Record& rec : records) {
    const double expected = bruteForceWeight(renderer, rec, heuristic, roulette);
    ASSERT_NEAR(rec.weight, expected, 2e-4 * std::max(1.0, expected))
        << name << ": strategy s=" << rec.s << " t=" << rec.path.size() - rec.s;
    ++checked;
    for (const PathVertex& v : rec.path) withDelta += v.type == PathVertex::Type::Surface && v.delta;
  }
  EXPECT_GT(checked, 1000);
  if (name == "glass-cube") EXPECT_GT(withDelta, 0) << "glass-cube paths should cross smooth glass";
}

// A glossy or smooth vertex's BSDF roughened by `scale` (smooth ones as Beckmann 1e-4 first), as a
// connection hook may put at the ends (relt's tempered levels); none for a diffuse vertex.
std::optional<Bsdf> roughened(const PathVertex& v, float scale) {
  if (!v.isSurface() || v.bsdf->material().kind == MaterialKind::Lambert) return std::nullopt;
  const Material& m = v.bsdf->material();
  const bool smooth = m.alpha <= 0.0f;
  return Bsdf(m, v.sp.ns, v.sp.ng, Roughness{scale * (smooth ? 1e-4f : m.alpha), smooth ? Microfacet::Beckmann : m.distribution});
}

// Weights with other end BSDFs (what a connection hook asks for): with the connection vertices'
// BSDFs replaced by roughened ones, the renderer's weight equals the brute-force weight of the
// path whose two connection vertices carry those BSDFs for every strategy. ring with glossy
// metals, so that connections at metal vertices exist unchanged and are observed.
void checkTemperedWeights(float scale) {
  RenderSettings settings;
  settings.width = settings.height = 32;
  Renderer renderer(test::glossyRing(), settings);
  Bdpt bdpt(renderer.context());
  int checked = 0;
  bdpt.setObserver([&](std::span<const PathVertex> light, std::span<const PathVertex> camera, float, const Color&) {
    std::vector<PathVertex> l(light.begin(), light.end()), c(camera.begin(), camera.end());
    auto tempered = [&](const PathVertex& v) { return roughened(v, scale); };
    const std::optional<Bsdf> bL = l.empty() ? std::nullopt : tempered(l.back());
    const std::optional<Bsdf> bC = tempered(c.back());
    if (!bL && !bC) return;
    const float w = bdpt.misWeight(l, c, bL ? &*bL : nullptr, bC ? &*bC : nullptr);
    Record rec;
    rec.s = static_cast<int>(l.size());
    rec.path = l;
    for (auto it = c.rbegin(); it != c.rend(); ++it) rec.path.push_back(*it);
    if (bL) rec.path[size_t(rec.s - 1)].bsdf = bL;
    if (bC) rec.path[size_t(rec.s)].bsdf = bC;
    const double expected = bruteForceWeight(renderer, rec, MisHeuristic::Power, true);
    ASSERT_NEAR(w, expected, 2e-4 * std::max(1.0, expected)) << "strategy s=" << rec.s;
    ++checked;
  });
  PathSample sample;
  for (uint64_t i = 0; i < 4000 && checked < 5000; ++i) {
    IndependentSource source(hashKey(77, i));
    bdpt.trace(Vec2(source.next(SampleStream::Camera) * 32, source.next(SampleStream::Camera) * 32), source, sample);
    sample.clear();
  }
  EXPECT_GT(checked, 200);
}

}  // namespace

TEST(BdptMis, PowerHeuristicWeightsMatchBruteForceOnCornellBox) { checkScene("cornell-box", MisHeuristic::Power); }
TEST(BdptMis, PowerHeuristicWeightsMatchBruteForceOnGlassCube) { checkScene("glass-cube", MisHeuristic::Power); }
TEST(BdptMis, BalanceHeuristicWeightsMatchBruteForceOnCornellBox) { checkScene("cornell-box", MisHeuristic::Balance); }
// Without roulette (what mmlt uses) the densities carry no continuation probability.
TEST(BdptMis, WeightsWithoutRouletteMatchBruteForceOnGlassCube) {
  checkScene("glass-cube", MisHeuristic::Power, false);
}

TEST(BdptMis, TemperedConnectionWeightsMatchBruteForceOnGlossyRing) {
  checkTemperedWeights(10.0f);  // T = 100
  checkTemperedWeights(50.0f);  // T = 2500
}
