// BDPT with a minimum path length (the directly seen emission estimated apart): leaving out paths
// of one segment removes exactly the camera-ray-hits-emitter splat and changes nothing else.
#include <gtest/gtest.h>

#include "path/bdpt.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"
#include "test_support.h"

using namespace relt;

TEST(BdptMinDepth, LeavingOutOneSegmentPathsRemovesOnlyTheDirectlySeenEmission) {
  RenderSettings settings;
  settings.width = 32;
  settings.height = 32;
  settings.maxDepth = 8;
  const Renderer renderer(loadGltf(test::sourcePath("scenes/cornell-box.gltf")), settings);
  PathContext withoutDirect = renderer.context();
  withoutDirect.settings.minDepth = 2;
  Bdpt all(renderer.context()), longer(withoutDirect);
  int removed = 0, samples = 0;
  for (int y = 0; y < settings.height; ++y)
    for (int x = 0; x < settings.width; ++x) {
      IndependentSource ua(hashKey(11, uint64_t(y * settings.width + x))), ub(hashKey(11, uint64_t(y * settings.width + x)));
      PathSample a, b;
      const Vec2 film(x + 0.5f, y + 0.5f);
      all.trace(film, ua, a);
      longer.trace(film, ub, b);
      ++samples;
      // b must be a with at most one splat taken out, and that splat a directly seen emitter (L1).
      ASSERT_LE(b.splats.size(), a.splats.size());
      ASSERT_GE(b.splats.size() + 1, a.splats.size());
      size_t j = 0;
      for (size_t i = 0; i < a.splats.size(); ++i) {
        if (j < b.splats.size() && a.splats[i].value == b.splats[j].value && a.splats[i].cls == b.splats[j].cls) {
          ++j;
          continue;
        }
        EXPECT_EQ(a.splats[i].cls, PathClass::L1);
        ++removed;
      }
      EXPECT_EQ(j, b.splats.size());
    }
  // The ceiling light covers some of these pixels, and only those lose a splat.
  EXPECT_GT(removed, 0);
  EXPECT_LT(removed, samples / 10);
}
