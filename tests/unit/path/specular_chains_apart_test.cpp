// BDPT with the camera - specular* - emitter paths left to the pass apart: that removes exactly the
// splats of emission found by the camera subpath after specular vertices only (s = 0) and changes
// nothing else, and the pass (path/specular_chain.h) finds emission of both kinds there.
#include <gtest/gtest.h>

#include "path/bdpt.h"
#include "path/specular_chain.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"
#include "test_support.h"

using namespace relt;

namespace {

struct Removed {
  int direct = 0, throughSpecular = 0, samples = 0;
};

// A 32 x 32 image, 4 x 4 positions in every pixel, with and without those paths on the same streams.
Removed removedSplats(const char* scene) {
  RenderSettings settings;
  settings.width = 32;
  settings.height = 32;
  settings.maxDepth = 8;
  const Renderer renderer(loadGltf(test::sourcePath(scene)), settings);
  PathContext apart = renderer.context();
  apart.settings.specularChainsApart = true;
  Bdpt all(renderer.context()), rest(apart);
  Removed removed;
  for (int y = 0; y < settings.height; ++y)
    for (int x = 0; x < settings.width; ++x)
      for (int k = 0; k < 16; ++k) {
        const uint64_t pixel = uint64_t(y * settings.width + x);
        IndependentSource ua(hashKey(11, pixel, uint64_t(k))), ub(hashKey(11, pixel, uint64_t(k)));
        PathSample a, b;
        const Vec2 film(x + (k % 4 + 0.5f) / 4, y + (k / 4 + 0.5f) / 4);
        all.trace(film, ua, a);
        rest.trace(film, ub, b);
        ++removed.samples;
        // b must be a with some splats taken out, each of them emission found (L1 seen directly,
        // L0 after specular bounces).
        EXPECT_LE(b.splats.size(), a.splats.size());
        size_t j = 0;
        for (size_t i = 0; i < a.splats.size(); ++i) {
          if (j < b.splats.size() && a.splats[i].value == b.splats[j].value && a.splats[i].cls == b.splats[j].cls) {
            ++j;
            continue;
          }
          EXPECT_TRUE(a.splats[i].cls == PathClass::L1 || a.splats[i].cls == PathClass::L0);
          ++(a.splats[i].cls == PathClass::L1 ? removed.direct : removed.throughSpecular);
        }
        EXPECT_EQ(j, b.splats.size());
      }
  return removed;
}

// The pass's emission of one class over a 32 x 32 image, 4 x 4 positions in every pixel.
Color passSum(const char* scene, PathClass cls) {
  RenderSettings settings;
  settings.width = 32;
  settings.height = 32;
  const Renderer renderer(loadGltf(test::sourcePath(scene)), settings);
  Color sum(0.0f);
  for (int y = 0; y < settings.height; ++y)
    for (int x = 0; x < settings.width; ++x) {
      for (int k = 0; k < 16; ++k) {
        IndependentSource u(hashKey(12, uint64_t(y * settings.width + x), uint64_t(k)));
        PathSample s;
        traceSpecularChain(renderer.context(), Vec2(x + (k % 4 + 0.5f) / 4, y + (k / 4 + 0.5f) / 4), u, s);
        for (const Splat& splat : s.splats)
          if (splat.cls == cls) sum += splat.value;
      }
    }
  return sum;
}

}  // namespace

TEST(SpecularChainsApart, OnADiffuseSceneOnlyTheDirectlySeenEmissionIsRemoved) {
  const Removed r = removedSplats("scenes/cornell-box.gltf");
  // The ceiling light covers some of these pixels, and only those lose a splat.
  EXPECT_GT(r.direct, 0);
  EXPECT_LT(r.direct, r.samples / 10);
  EXPECT_EQ(r.throughSpecular, 0);
}

TEST(SpecularChainsApart, ThroughMirrorsTheEmissionSeenInThemIsRemovedToo) {
  const Removed r = removedSplats("scenes/mirror-balls.gltf");
  EXPECT_GT(r.throughSpecular, 0) << "the light is seen in the mirror balls";
}

TEST(SpecularChain, FindsTheEmissionSeenDirectlyAndInMirrors) {
  EXPECT_GT(maxComponent(passSum("scenes/mirror-balls.gltf", PathClass::L0)), 0.0f);
  EXPECT_GT(maxComponent(passSum("scenes/cornell-box.gltf", PathClass::L1)), 0.0f);
  EXPECT_EQ(maxComponent(passSum("scenes/cornell-box.gltf", PathClass::L0)), 0.0f) << "no specular surface there";
}
