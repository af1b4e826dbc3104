// Closest-hit throughput for incoherent rays: origins uniform in the scene's bounds, directions
// uniform on the sphere, one Embree thread. Prints rays per second.
#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "core/rng.h"
#include "core/sampling.h"
#include "scene/gltf_loader.h"
#include "scene/ray_tracer.h"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: relt_bench_rays SCENE [RAYS]\n");
    return 2;
  }
  const long count = argc > 2 ? std::atol(argv[2]) : 4000000;
  const relt::Scene scene = relt::loadGltf(argv[1]);
  const relt::RayTracer tracer(scene);
  relt::Rng rng(42);
  std::vector<relt::Ray> rays(static_cast<size_t>(count));
  const relt::Vec3 lo = scene.bounds.lo, ext = scene.bounds.hi - scene.bounds.lo;
  for (auto& r : rays) {
    r.origin = lo + ext * relt::Vec3(rng.uniform(), rng.uniform(), rng.uniform());
    r.dir = relt::uniformSphere(relt::Vec2(rng.uniform(), rng.uniform()));
  }
  long hits = 0;
  const auto t0 = std::chrono::steady_clock::now();
  for (const auto& r : rays) {
    relt::SurfacePoint sp;
    float d;
    hits += tracer.intersect(r, sp, d);
  }
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("{\"scene\": \"%s\", \"rays\": %ld, \"hits\": %ld, \"seconds\": %.3f, \"rays_per_second\": %.0f}\n",
              argv[1], count, hits, s, count / s);
  return 0;
}
