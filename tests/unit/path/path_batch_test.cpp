// tracePaths (neighbouring pixels traced together, their first rays as packets) gives every
// sample the same splats as tracePath: each path draws the same numbers from its own source.
#include <gtest/gtest.h>

#include <vector>

#include "path/path_tracer.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"
#include "test_support.h"

using namespace relt;

namespace {

bool sameSplats(const PathSample& a, const PathSample& b) {
  if (a.splats.size() != b.splats.size()) return false;
  for (size_t i = 0; i < a.splats.size(); ++i) {
    const Splat &x = a.splats[i], &y = b.splats[i];
    if (x.film != y.film || x.cls != y.cls || x.value != y.value) return false;
  }
  return true;
}

}  // namespace

TEST(PathBatch, BatchedPathsEqualSinglePaths) {
  for (const char* name : {"cornell-box", "glass-cube", "ring"}) {
    RenderSettings settings;
    settings.width = 37;  // rows that do not divide into packets
    settings.height = 24;
    settings.maxDepth = 8;
    const Renderer renderer(loadGltf(test::sourcePath(std::string("scenes/") + name + ".gltf")), settings);
    const PathContext& ctx = renderer.context();
    int samples = 0, differ = 0, withLight = 0;
    for (int y = 0; y < settings.height; ++y) {
      const int n = settings.width;
      std::vector<IndependentSource> batchSources(n), singleSources(n);
      std::vector<SampleSource*> pointers(n);
      std::vector<Vec2> film(n);
      std::vector<PathSample> batched(n);
      for (int x = 0; x < n; ++x) {
        batchSources[x].reset(hashKey(3, uint64_t(y * n + x)));
        singleSources[x].reset(hashKey(3, uint64_t(y * n + x)));
        pointers[x] = &batchSources[x];
        film[x] = Vec2(x + 0.5f, y + 0.5f);
      }
      tracePaths(ctx, n, film.data(), pointers.data(), batched.data());
      for (int x = 0; x < n; ++x) {
        PathSample single;
        tracePath(ctx, film[x], singleSources[x], single);
        ++samples;
        differ += !sameSplats(single, batched[x]);
        withLight += !single.splats.empty();
      }
    }
    // A ray grazing an edge may go either way between the packet and single-ray kernels.
    EXPECT_LE(differ, samples / 200) << name << ": " << differ << " of " << samples << " samples differ";
    EXPECT_GT(withLight, samples / 4) << name << ": most paths must carry light for the comparison to mean anything";
  }
}
