// Tempered connection BSDFs: which vertices a level roughens and how (DESIGN §3.1), and that the
// per-level targets the hook on the path builder sums are I itself wherever a level changes nothing.
#include <gtest/gtest.h>

#include <cmath>

#include "path/bdpt.h"
#include "replica/tempered_targets.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"
#include "test_support.h"

using namespace relt;

namespace {

Material conductor(float alpha) {
  Material m;
  m.kind = MaterialKind::Conductor;
  m.alpha = alpha;
  m.distribution = Microfacet::GGX;
  return m;
}

// levelTargets and I(u) of `count` independent samples.
struct Targets {
  std::vector<std::vector<double>> q;
  std::vector<double> target;
};
Targets traceTargets(const std::string& name, const Tempering& tempering, int count) {
  RenderSettings settings;
  settings.width = settings.height = 32;
  Renderer renderer(loadGltf(test::sourcePath("scenes/" + name + ".gltf")), settings);
  Bdpt bdpt(renderer.context());
  TemperedTargets hook(tempering);
  bdpt.setConnectionHook(&hook);
  Targets out;
  PathSample sample;
  for (int i = 0; i < count; ++i) {
    IndependentSource source(hashKey(31, uint64_t(i)));
    sample.clear();
    bdpt.trace(Vec2(source.next(SampleStream::Camera) * 32, source.next(SampleStream::Camera) * 32), source, sample);
    out.q.emplace_back(hook.levelTargets().begin(), hook.levelTargets().end());
    out.target.push_back(sample.target());
  }
  return out;
}

}  // namespace

TEST(Tempering, DiffuseKeepsItsBsdfAndSmoothStaysDeltaAtTemperatureOne) {
  Tempering t;
  t.scale = {1.0f, 10.0f};
  Material lambert;
  EXPECT_FALSE(t.roughness(lambert, 1).has_value());
  EXPECT_FALSE(t.roughness(conductor(0.0f), 0).has_value());
  EXPECT_FALSE(t.roughness(conductor(0.3f), 0).has_value());
}

TEST(Tempering, RoughensBySqrtTAndTreatsSmoothAsBeckmann) {
  Tempering t;
  t.scale = {1.0f, 10.0f};
  const auto rough = t.roughness(conductor(0.3f), 1);
  ASSERT_TRUE(rough.has_value());
  EXPECT_FLOAT_EQ(rough->alpha, 3.0f);
  EXPECT_EQ(rough->distribution, Microfacet::GGX);
  const auto smooth = t.roughness(conductor(0.0f), 1);
  ASSERT_TRUE(smooth.has_value());
  EXPECT_FLOAT_EQ(smooth->alpha, 10.0f * Tempering::kSmoothAlpha);
  EXPECT_EQ(smooth->distribution, Microfacet::Beckmann);
}

TEST(Tempering, RegularisationIsAFloorAppliedBeforeTempering) {
  Tempering t;
  t.scale = {1.0f, 4.0f};
  t.minAlpha = 0.1f;
  EXPECT_FLOAT_EQ(t.roughness(conductor(0.0f), 0)->alpha, 0.1f);   // smooth, T = 1: the floor
  EXPECT_FLOAT_EQ(t.roughness(conductor(0.02f), 1)->alpha, 0.4f);  // sqrt(T) max(alpha, reg)
  EXPECT_FALSE(t.roughness(conductor(0.5f), 0).has_value());      // already rougher than the floor
  EXPECT_FLOAT_EQ(t.roughness(conductor(0.5f), 1)->alpha, 2.0f);
}

TEST(Tempering, TemperaturesAreGeometricFromOneToTheMaximum) {
  const std::vector<double> t = geometricTemperatures(5, 10000.0);
  ASSERT_EQ(t.size(), 5u);
  for (int k = 0; k < 5; ++k) EXPECT_NEAR(t[size_t(k)], std::pow(10.0, k), 1e-9 * std::pow(10.0, k));
}

// Levels that change nothing (T = 1, or only diffuse surfaces at the connections) target I itself.
TEST(TemperedTargets, UntemperedLevelsEqualTheTargetOfThePath) {
  Tempering t;
  t.scale = {1.0f, 1.0f};
  for (const char* scene : {"glass-cube", "ring"}) {
    const Targets r = traceTargets(scene, t, 3000);
    int lit = 0;
    for (size_t i = 0; i < r.q.size(); ++i) {
      ASSERT_EQ(r.q[i].size(), 2u);
      EXPECT_NEAR(r.q[i][0], r.target[i], 1e-5 * std::max(1.0, r.target[i])) << scene;
      EXPECT_EQ(r.q[i][0], r.q[i][1]);
      lit += r.target[i] > 0.0;
    }
    EXPECT_GT(lit, 100) << scene;
  }
}

TEST(TemperedTargets, DiffuseSceneIsTheSameAtEveryTemperature) {
  Tempering t;
  t.scale = {1.0f, 50.0f};
  const Targets r = traceTargets("cornell-box", t, 2000);
  for (size_t i = 0; i < r.q.size(); ++i) EXPECT_EQ(r.q[i][0], r.q[i][1]);
}

// ring's mirrors: at T = 2500 connections through mirror vertices become possible, so the hot level
// sees light on paths where I (the cold level) has none, and never loses any.
TEST(TemperedTargets, HotLevelConnectsThroughMirrors) {
  Tempering t;
  t.scale = {1.0f, 50.0f};
  const Targets r = traceTargets("ring", t, 20000);
  int gained = 0;
  for (size_t i = 0; i < r.q.size(); ++i) {
    if (r.q[i][0] == 0.0 && r.q[i][1] > 0.0) ++gained;
    EXPECT_GE(r.q[i][1], 0.0);
  }
  EXPECT_GT(gained, 0);
}
