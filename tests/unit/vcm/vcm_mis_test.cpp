// VCM's recursive MIS against brute force: for camera walks that end on an emitter, the weight
// VcmMis gives every technique that can make the path (emission found, next-event estimation,
// each connection, light tracing, merging at each non-specular vertex) equals the weight from
// every technique's explicit density (Veach 1997 §9; thesis digest §1.6), and they sum to 1.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>

#include "core/rng.h"
#include "path/vertex.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"
#include "test_support.h"
#include "vcm/vcm_mis.h"

using namespace relt;

namespace {

struct Point {
  SurfacePoint sp;
  std::optional<Bsdf> bsdf;
  bool delta() const { return bsdf->isDelta(); }
};
using Path = std::vector<Point>;  // x_0 on an emitter .. x_{n-1}; the camera is x_n

// Camera random walks; every vertex on an emitter closes a path (the walk goes on for longer ones).
std::vector<Path> emitterPaths(const PathContext& ctx, int walks, int maxDepth) {
  std::vector<Path> paths;
  Rng rng(11, 3);
  for (int k = 0; k < walks; ++k) {
    Path walk;
    Vec3 from = ctx.camera.position();
    Ray ray{from, ctx.camera.direction(Vec2(rng.uniform(), rng.uniform()) * Vec2(ctx.camera.width(), ctx.camera.height()))};
    while (int(walk.size()) < maxDepth) {
      SurfacePoint hit;
      float distance;
      if (!ctx.tracer.intersect(ray, hit, distance)) break;
      const Vec3 wo = glm::normalize(from - hit.p);
      walk.push_back({hit, Bsdf(ctx.scene.materials[hit.material], hit.ns, hit.ng)});
      if (!isBlack(ctx.lights.emitted(hit, wo))) paths.emplace_back(walk.rbegin(), walk.rend());
      // No subpath goes on from a vertex Russian roulette always ends (a black emitter).
      if (!(continuationProbability(ctx.scene.materials[hit.material]) > 0.0f)) break;
      const auto bs = walk.back().bsdf->sample(wo, Vec2(rng.uniform(), rng.uniform()), rng.uniform(), TransportMode::Radiance);
      if (!bs || !(bs->pdf > 0.0f)) break;
      from = hit.p;
      ray = ctx.tracer.spawn(hit, bs->wi);
    }
  }
  return paths;
}

class Techniques {
 public:
  Techniques(const PathContext& ctx, const VcmIteration& it, const Path& x)
      : ctx_(ctx), mis_(ctx, it), x_(x), n_(int(x.size())),
        eta_(std::numbers::pi * double(it.radius) * it.radius * it.lightPaths), kappa_(it.lightSubpathFactor),
        mode_(it.mode) {}

  // Every valid technique's weight, recursive and brute force, as (recursive, brute) pairs.
  std::vector<std::pair<double, double>> weights() const {
    std::vector<double> density, recursive;
    for (int s = 0; s <= n_; ++s)
      if (connectionValid(s)) {
        density.push_back(connectionDensity(s) * (s >= 2 ? kappa_ : 1.0));
        recursive.push_back(connectionWeight(s));
      }
    for (int k = 1; k < n_; ++k)
      if (mode_ == VcmMode::Vcm && !x_[size_t(k)].delta()) {
        density.push_back(connectionDensity(k + 1) * cameraDensity(k) * eta_ * kappa_);
        const VcmSubpath camera = cameraState(k);
        recursive.push_back(mis_.mergeWeight(camera, towardsCamera(k), *x_[size_t(k)].bsdf, lightVertex(k)));
      }
    const double beta = misExponent(ctx_.settings.heuristic);
    double sum = 0.0;
    for (double p : density) sum += std::pow(p, beta);
    std::vector<std::pair<double, double>> out;
    for (size_t i = 0; i < density.size(); ++i) out.emplace_back(recursive[i], std::pow(density[i], beta) / sum);
    return out;
  }

 private:
  Vec3 position(int i) const { return i == n_ ? ctx_.camera.position() : x_[size_t(i)].sp.p; }
  Vec3 dir(int from, int to) const { return glm::normalize(position(to) - position(from)); }
  Vec3 towardsCamera(int i) const { return dir(i, i + 1); }
  uint32_t light() const { return ctx_.lights.lightOfTriangle(x_[0].sp.triangle); }
  // Solid angle density at `from` towards x_to, as an area density there.
  double toArea(double pdfW, int from, int to) const {
    const Vec3 d = position(to) - position(from);
    const double dist2 = glm::dot(d, d);
    return pdfW * std::abs(glm::dot(x_[size_t(to)].sp.ng, d)) / std::sqrt(dist2) / dist2;
  }
  // x_i's density from the light end and from the camera end (a delta's solid angle density is
  // taken as 1 both ways: every technique that can make the path has one of the two).
  double lightDensity(int i) const {
    if (i == 0) return ctx_.lights.pdfPick(light()) * ctx_.lights.pdfPosition(light());
    if (i == 1) return toArea(ctx_.lights.pdfDirection(light(), x_[0].sp, dir(0, 1)), 0, 1);
    const Point& v = x_[size_t(i - 1)];
    const double q = continuationProbability(v.bsdf->material());
    return toArea(v.delta() ? 1.0 : v.bsdf->pdf(dir(i - 1, i - 2), dir(i - 1, i)) * q, i - 1, i);
  }
  double cameraDensity(int i) const {
    if (i == n_ - 1) return toArea(ctx_.camera.pdfDirection(dir(n_, i)), n_, i);
    const Point& v = x_[size_t(i + 1)];
    const double q = continuationProbability(v.bsdf->material());
    return toArea(v.delta() ? 1.0 : v.bsdf->pdf(dir(i + 1, i + 2), dir(i + 1, i)) * q, i + 1, i);
  }
  double connectionDensity(int s) const {
    double p = 1.0;
    for (int i = 0; i < s; ++i) p *= lightDensity(i);
    for (int i = s; i < n_; ++i) p *= cameraDensity(i);
    return p;
  }
  // s light vertices x_0 .. x_{s-1}, the rest from the camera; (1, 1) is not used.
  bool connectionValid(int s) const {
    if (s == 0) return true;
    if (n_ == 1) return false;
    if (s == n_) return !x_[size_t(n_ - 1)].delta();
    return (s == 1 || !x_[size_t(s - 1)].delta()) && !x_[size_t(s)].delta();
  }
  // The camera subpath arrived at x_m, and the light subpath at x_m as a stored vertex.
  VcmSubpath cameraState(int m) const {
    VcmSubpath c;
    mis_.startCamera(c, ctx_.camera.pdfDirection(dir(n_, n_ - 1)));
    for (int i = n_ - 1; i >= m; --i) {
      EXPECT_TRUE(mis_.arrive(c, x_[size_t(i)].sp));
      if (i > m) mis_.scatter(c, *x_[size_t(i)].bsdf, x_[size_t(i)].sp, dir(i, i + 1), dir(i, i - 1));
    }
    return c;
  }
  LightPoint lightPoint() const {
    LightPoint lp;
    lp.light = light();
    lp.sp = x_[0].sp;
    lp.pdfPick = ctx_.lights.pdfPick(light());
    lp.pdfPos = ctx_.lights.pdfPosition(light());
    return lp;
  }
  LightVertex lightVertex(int m) const {
    VcmSubpath l;
    mis_.startLight(l, lightPoint(), ctx_.lights.pdfDirection(light(), x_[0].sp, dir(0, 1)),
                    std::abs(glm::dot(x_[0].sp.ng, dir(0, 1))));
    for (int i = 1; i <= m; ++i) {
      EXPECT_TRUE(mis_.arrive(l, x_[size_t(i)].sp));
      if (i < m) mis_.scatter(l, *x_[size_t(i)].bsdf, x_[size_t(i)].sp, dir(i, i - 1), dir(i, i + 1));
    }
    return LightVertex{x_[size_t(m)].sp, dir(m, m - 1), Color(1.0f), l.dVCM, l.dVC, l.dVM, m};
  }
  double connectionWeight(int s) const {
    if (s == 0) return mis_.emissionWeight(cameraState(0), x_[0].sp, towardsCamera(0));
    if (s == n_) return mis_.lightTracingWeight(lightVertex(n_ - 1), *x_[size_t(n_ - 1)].bsdf);
    const VcmSubpath camera = cameraState(s);
    const Point& xs = x_[size_t(s)];
    if (s == 1) return mis_.nextEventWeight(camera, xs.sp, towardsCamera(1), *xs.bsdf, lightPoint());
    return mis_.connectWeight(camera, xs.sp, towardsCamera(s), *xs.bsdf, lightVertex(s - 1), *x_[size_t(s - 1)].bsdf);
  }

  const PathContext& ctx_;
  VcmMis mis_;
  const Path& x_;
  int n_;
  double eta_;
  double kappa_;  // the light subpath techniques' density factor (s >= 2, light tracing, merging)
  VcmMode mode_;
};

void checkScene(const std::string& name, VcmMode mode, MisHeuristic heuristic, double lightSubpathFactor = 1.0) {
  RenderSettings settings;
  settings.width = settings.height = 32;
  settings.heuristic = heuristic;
  Renderer renderer(loadGltf(test::sourcePath("scenes/" + name + ".gltf")), settings);
  const PathContext& ctx = renderer.context();
  VcmIteration it;
  it.mode = mode;
  it.radius = 0.01f * glm::length(ctx.scene.bounds.diagonal());
  it.lightPaths = 32.0 * 32.0;
  it.lightSubpathFactor = lightSubpathFactor;
  int checked = 0, withDelta = 0, lengths[9] = {};
  for (const Path& path : emitterPaths(ctx, 60000, 8)) {
    bool delta = false;
    for (const Point& p : path) delta |= p.delta();
    double sum = 0.0;
    const auto weights = Techniques(ctx, it, path).weights();
    std::string all;
    for (const auto& [recursive, brute] : weights) all += " " + std::to_string(recursive) + "/" + std::to_string(brute);
    std::string deltas;
    for (const Point& p : path) deltas += p.delta() ? "D" : "-";
    for (const auto& [recursive, brute] : weights) {
      ASSERT_NEAR(recursive, brute, 1e-3 + 1e-3 * brute) << name << ", path of " << path.size() << " segments " << deltas << all;
      sum += recursive;
    }
    EXPECT_NEAR(sum, 1.0, 2e-3) << name << ", path of " << path.size() << " segments";
    ++checked;
    withDelta += delta;
    ++lengths[path.size()];
  }
  EXPECT_GT(checked, 300) << name;
  for (int n = 1; n <= 4; ++n) EXPECT_GT(lengths[n], 10) << name << ": paths of " << n << " segments";
  if (name == "glass-cube") EXPECT_GT(withDelta, 30) << "glass-cube paths should cross smooth glass";
}

}  // namespace

TEST(VcmMis, EveryTechniquesWeightIsTheBruteForceOneOnCornellBox) {
  checkScene("cornell-box", VcmMode::Vcm, MisHeuristic::Power);
  checkScene("cornell-box", VcmMode::Vcm, MisHeuristic::Balance);
}
TEST(VcmMis, EveryTechniquesWeightIsTheBruteForceOneOnGlassCube) {
  checkScene("glass-cube", VcmMode::Vcm, MisHeuristic::Power);
}
TEST(VcmMis, ConnectionsOnlyWeightsAreBdptsOnGlassCube) { checkScene("glass-cube", VcmMode::Bpt, MisHeuristic::Power); }
// meb's visibility chain weighs its light subpath techniques by 1 / b_vis: with that factor on
// their densities the recursion still gives every technique its brute-force weight.
TEST(VcmMis, ALightSubpathFactorWeighsThoseTechniquesAsTheirDensitiesTimesIt) {
  checkScene("cornell-box", VcmMode::Vcm, MisHeuristic::Power, 3.7);
  checkScene("cornell-box", VcmMode::Vcm, MisHeuristic::Balance, 0.4);
  checkScene("glass-cube", VcmMode::Vcm, MisHeuristic::Power, 3.7);
  checkScene("glass-cube", VcmMode::Bpt, MisHeuristic::Balance, 3.7);
}
