// The Embree wrapper against brute force: closest hits and occlusion agree with a plain
// double-precision ray-triangle test over all triangles; ray packets answer as single rays do.
#include <gtest/gtest.h>

#include <limits>
#include <optional>

#include "core/rng.h"
#include "core/sampling.h"
#include "scene/gltf_loader.h"
#include "scene/ray_tracer.h"
#include "test_support.h"

using namespace relt;

namespace {

// Quads of consecutive triangles, of triangles paired across the mesh, and lone triangles (furnace).
const char* const kScenes[] = {"cornell-box", "ring", "glass-cube", "door-ajar", "torus-in-glass", "furnace"};

Scene load(const std::string& name) { return loadGltf(test::sourcePath("scenes/" + name + ".gltf")); }

struct BruteHit {
  uint32_t triangle;
  double t;
};

// Double-precision Moller-Trumbore over every triangle.
std::optional<BruteHit> bruteForce(const Scene& s, const Ray& ray) {
  std::optional<BruteHit> best;
  const glm::dvec3 o(ray.origin), d(ray.dir);
  for (uint32_t i = 0; i < s.triangles.size(); ++i) {
    const glm::dvec3 p0(s.positions[s.triangles[i].v[0]]), p1(s.positions[s.triangles[i].v[1]]),
        p2(s.positions[s.triangles[i].v[2]]);
    const glm::dvec3 e1 = p1 - p0, e2 = p2 - p0, pv = glm::cross(d, e2);
    const double det = glm::dot(e1, pv);
    if (std::abs(det) < 1e-14) continue;
    const glm::dvec3 tv = o - p0;
    const double u = glm::dot(tv, pv) / det;
    const glm::dvec3 qv = glm::cross(tv, e1);
    const double v = glm::dot(d, qv) / det, t = glm::dot(e2, qv) / det;
    if (u < 0.0 || v < 0.0 || u + v > 1.0 || t <= 0.0) continue;
    if (!best || t < best->t) best = BruteHit{i, t};
  }
  return best;
}

}  // namespace

TEST(RayTracer, ClosestHitsAndOcclusionMatchBruteForce) {
  for (const char* name : kScenes) {
    const Scene s = load(name);
    const RayTracer tracer(s);
    Rng rng(5);
    const Vec3 lo = s.bounds.lo, ext = s.bounds.hi - s.bounds.lo;
    const float scale = glm::length(ext);
    int hits = 0, mismatched = 0;
    for (int i = 0; i < 3000; ++i) {
      const Ray ray{lo + ext * Vec3(rng.uniform(), rng.uniform(), rng.uniform()),
                    uniformSphere(Vec2(rng.uniform(), rng.uniform())), INFINITY};
      SurfacePoint sp;
      float dist = 0.0f;
      const bool hit = tracer.intersect(ray, sp, dist);
      const std::optional<BruteHit> ref = bruteForce(s, ray);
      // Rays grazing an edge can legitimately go either way in float; they are counted, not failed.
      if (hit != ref.has_value() || (hit && std::abs(dist - ref->t) > 1e-4 * scale)) {
        ++mismatched;
        continue;
      }
      if (!hit) continue;
      ++hits;
      EXPECT_LT(glm::length(sp.p - (ray.origin + dist * ray.dir)), 1e-4f * scale) << name;
      if (sp.triangle != ref->triangle)  // a tie at a shared edge: same distance, other triangle
        EXPECT_NEAR(dist, ref->t, 1e-5 * scale) << name;
      EXPECT_EQ(sp.material, s.triangles[sp.triangle].material);
      // Occlusion: nothing blocks the segment just short of the hit; the segment past it is blocked.
      const Vec3 justBefore = ray.origin + 0.999f * dist * ray.dir;
      if (dist < 1e-3f * scale) continue;  // closer than a few ray offsets (1e-4 x |coordinates|)
      EXPECT_FALSE(tracer.occludedToPoint(ray.origin, -ray.dir, justBefore)) << name;
      if (dist < 0.5f * scale) {
        const Vec3 beyond = ray.origin + std::min(1.5f * dist + 1e-2f * scale, 2.0f * scale) * ray.dir;
        EXPECT_TRUE(tracer.occludedToPoint(ray.origin, -ray.dir, beyond)) << name;
      }
    }
    EXPECT_GT(hits, 1000) << name;
    EXPECT_LT(mismatched, 3) << name;
  }
}

// Hit points on quads of very large and very small triangles (the loader allows coordinates up to
// 1e15): the barycentrics, computed from the hit position, stay finite and put the point where
// the ray meets the plane.
TEST(RayTracer, HitPointsOnHugeAndTinyQuadsLieOnTheRay) {
  for (const float size : {1e12f, 1e-8f}) {
    Scene s;
    s.positions = {{0, 0, 0}, {size, 0, 0}, {size, size, 0}, {0, size, 0}};
    s.normals.assign(4, Vec3(0.0f));
    s.triangles = {{{0, 1, 2}, 0}, {{0, 2, 3}, 0}};
    s.materials.resize(1);
    for (const Vec3& p : s.positions) s.bounds.extend(p);
    const RayTracer tracer(s);
    Rng rng(3);
    for (int i = 0; i < 200; ++i) {
      const Vec3 target(rng.uniform() * size, rng.uniform() * size, 0.0f);
      const Vec3 origin = target + Vec3(0.3f, -0.2f, 1.0f) * size;
      const Ray ray{origin, glm::normalize(target - origin), INFINITY};
      SurfacePoint sp;
      float dist = 0.0f;
      ASSERT_TRUE(tracer.intersect(ray, sp, dist)) << size;
      ASSERT_TRUE(std::isfinite(sp.p.x) && std::isfinite(sp.p.y) && std::isfinite(sp.p.z)) << size;
      EXPECT_LT(glm::length(sp.p - target), 1e-4f * size) << size;
      EXPECT_EQ(sp.triangle, target.x >= target.y ? 0u : 1u) << size << " " << target.x << " " << target.y;
    }
  }
}

// Rays Embree would reject (a NaN or infinite component, or one beyond its 1.8e18 limit, in the
// origin or the direction alone) miss everything instead of tripping Embree's assertion, which
// ends the process; a shadow ray towards such a point must not trip it either (what it answers
// does not matter: the sample is dropped as non-finite).
TEST(RayTracer, RaysEmbreeWouldRejectMissInsteadOfAborting) {
  const Scene s = load("cornell-box");
  const RayTracer tracer(s);
  const Vec3 inside = 0.5f * (s.bounds.lo + s.bounds.hi);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const Vec3 bad[] = {Vec3(nan, 0, 0), Vec3(0, INFINITY, 0), Vec3(0, 0, -2e18f)};
  for (const Vec3& b : bad) {
    SurfacePoint sp;
    float dist = 0.0f;
    EXPECT_FALSE(tracer.intersect(Ray{inside, b, INFINITY}, sp, dist)) << "direction " << b.x << " " << b.y << " " << b.z;
    EXPECT_FALSE(tracer.intersect(Ray{b, Vec3(0, 1, 0), INFINITY}, sp, dist)) << "origin " << b.x << " " << b.y << " " << b.z;
    tracer.occludedToPoint(inside, Vec3(0, 1, 0), inside + b);
  }
}

// Packets (camera rays of neighbouring pixels, random rays, rays Embree would reject, batches of
// every size up to a packet) give the single-ray answers. The packet and single-ray kernels use
// the same intersection arithmetic; a ray grazing an edge may still go either way, so a handful
// of differences in 5,000 queries per scene is allowed, no more.
TEST(RayTracer, PacketsAnswerAsSingleRays) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (const char* name : kScenes) {
    const Scene s = load(name);
    const RayTracer tracer(s);
    const Vec3 lo = s.bounds.lo, ext = s.bounds.hi - s.bounds.lo;
    const Vec3 eye = 0.5f * (lo + s.bounds.hi);
    Rng rng(9);
    int queries = 0, differ = 0, occludedQueries = 0, occludedDiffer = 0, blockedSeen = 0;
    for (int batch = 0; batch < 600; ++batch) {
      const int n = 1 + batch % RayTracer::kPacketSize;
      const bool coherent = batch % 2 == 0;
      const Vec3 centre = uniformSphere(Vec2(rng.uniform(), rng.uniform()));
      Ray rays[RayTracer::kPacketSize];
      for (int i = 0; i < n; ++i) {
        rays[i].origin = coherent ? eye : lo + ext * Vec3(rng.uniform(), rng.uniform(), rng.uniform());
        rays[i].dir = coherent ? glm::normalize(centre + 0.05f * Vec3(rng.uniform(), rng.uniform(), rng.uniform()))
                               : uniformSphere(Vec2(rng.uniform(), rng.uniform()));
      }
      if (batch % 7 == 3) rays[n / 2].dir = Vec3(nan, 0.0f, 0.0f);  // must miss, not abort
      SurfacePoint hits[RayTracer::kPacketSize];
      float dist[RayTracer::kPacketSize];
      bool found[RayTracer::kPacketSize];
      const uint64_t before = tracer.rayCount();
      tracer.intersect(rays, n, hits, dist, found);
      EXPECT_EQ(tracer.rayCount() - before, uint64_t(n));

      RayTracer::Segment segs[RayTracer::kPacketSize];
      for (int i = 0; i < n; ++i) {
        SurfacePoint sp;
        float d = 0.0f;
        const bool hit = tracer.intersect(rays[i], sp, d);
        ++queries;
        differ += hit != found[i] || (hit && (sp.triangle != hits[i].triangle || d != dist[i] || sp.p != hits[i].p));
        if (batch % 7 == 3 && i == n / 2) EXPECT_FALSE(found[i]) << name;
        // Segments from the ray's origin to a random point (some blocked, some not), every third
        // one inactive, some towards a punctual point.
        const Vec3 to = lo + ext * Vec3(rng.uniform(), rng.uniform(), rng.uniform());
        segs[i] = RayTracer::Segment{rays[i].origin, Vec3(0, 1, 0), to, Vec3(0, -1, 0), i % 2 == 0, i % 3 != 2};
      }
      bool blocked[RayTracer::kPacketSize];
      tracer.occluded(segs, n, blocked);
      for (int i = 0; i < n; ++i) {
        if (!segs[i].active) {
          EXPECT_FALSE(blocked[i]);
          continue;
        }
        const bool single = segs[i].toPoint ? tracer.occludedToPoint(segs[i].from, segs[i].fromNg, segs[i].to)
                                            : tracer.occluded(segs[i].from, segs[i].fromNg, segs[i].to, segs[i].toNg);
        ++occludedQueries;
        occludedDiffer += single != blocked[i];
        blockedSeen += single;
      }
    }
    EXPECT_LE(differ, queries / 1000) << name << ": " << differ << " of " << queries << " closest hits differ";
    EXPECT_LE(occludedDiffer, occludedQueries / 1000) << name;
    EXPECT_GT(blockedSeen, occludedQueries / 10) << name << ": the segments must test both answers";
    EXPECT_LT(blockedSeen, occludedQueries * 9 / 10) << name;
  }
}
