#pragma once
// Embree 3 wrapper: closest-hit and occlusion queries over the scene's triangles, plus the
// per-triangle data (geometric normal, area) that shading and light sampling need.
#include <vector>

#include "core/math.h"
#include "parallel/workers.h"
#include "scene/quad_pairs.h"
#include "scene/scene.h"

// Embree handles are opaque pointers; keep embree headers out of the rest of the renderer.
typedef struct RTCDeviceTy* RTCDevice;
typedef struct RTCSceneTy* RTCScene;

namespace relt {

struct Ray {
  Vec3 origin;
  Vec3 dir;     // unit length
  float tMax = INFINITY;
};

// A surface point reached by a ray or sampled on a light.
struct SurfacePoint {
  Vec3 p;
  Vec3 ng;           // unit geometric normal (triangle winding: front side)
  Vec3 ns;           // unit shading normal (== ng where the file gave no normals)
  uint32_t triangle = 0;
  uint32_t material = 0;
};

class RayTracer {
 public:
  explicit RayTracer(const Scene& scene);
  ~RayTracer();
  RayTracer(const RayTracer&) = delete;
  RayTracer& operator=(const RayTracer&) = delete;

  // Closest hit along the ray; false if it escapes. Counts rays for statistics.
  bool intersect(const Ray& ray, SurfacePoint& hit, float& distance) const;
  // True if anything blocks the open segment between two surface points (each offset off its surface).
  bool occluded(const Vec3& from, const Vec3& fromNg, const Vec3& to, const Vec3& toNg) const;
  // Same with a punctual point (no surface at the far end).
  bool occludedToPoint(const Vec3& from, const Vec3& fromNg, const Vec3& point) const;

  // Up to kPacketSize queries traced together as Embree ray packets. Coherent rays (camera rays of
  // neighbouring pixels and their first shadow rays) cost a fraction of single rays this way; the
  // results equal the single-ray queries' (same intersection arithmetic).
  static constexpr int kPacketSize = 16;
  // Closest hits of rays[0..n); found[i] is false where ray i escapes.
  void intersect(const Ray* rays, int n, SurfacePoint* hits, float* distance, bool* found) const;
  // An occlusion query as occluded() / occludedToPoint() take it; inactive segments are skipped.
  struct Segment {
    Vec3 from, fromNg, to, toNg;  // toNg unused when toPoint
    bool toPoint = false;
    bool active = false;
  };
  // blocked[i] as occluded() / occludedToPoint() would answer for segs[i] (false if inactive).
  void occluded(const Segment* segs, int n, bool* blocked) const;
  bool occluded(const Segment& seg) const;  // one active segment

  // Ray origin nudged off the surface to the side the direction goes to, by an offset proportional
  // to the coordinates' magnitude (float spacing grows with |p|). Inline: several per path vertex.
  Vec3 offsetOrigin(const Vec3& p, const Vec3& ng, const Vec3& dir) const {
    const Vec3 a = glm::abs(p);
    const float eps = kRayEpsilon * std::max(epsilonFloor_, std::max(a.x, std::max(a.y, a.z)));
    return p + (glm::dot(ng, dir) >= 0.0f ? eps : -eps) * ng;
  }
  Ray spawn(const SurfacePoint& sp, const Vec3& dir) const { return Ray{offsetOrigin(sp.p, sp.ng, dir), dir, INFINITY}; }

  const Scene& scene() const { return scene_; }
  float triangleArea(uint32_t t) const { return area_[t]; }
  const Vec3& triangleNormal(uint32_t t) const { return ng_[t]; }
  // The unit shading normal of a triangle whose vertex normals agree; zero where it varies.
  const Vec3& flatShadingNormal(uint32_t t) const { return flatNs_[t]; }
  // The point at barycentrics (b1, b2) of the triangle p0 p1 p2: every surface point's position
  // comes from here, so points rebuilt from copied corners equal the tracer's bit for bit.
  static Vec3 barycentricPoint(const Vec3& p0, const Vec3& p1, const Vec3& p2, float b1, float b2) {
    return (1.0f - b1 - b2) * p0 + b1 * p1 + b2 * p2;
  }
  // Surface point at barycentrics (b1, b2) of triangle t.
  SurfacePoint surfacePoint(uint32_t t, float b1, float b2) const {
    const Triangle& tri = scene_.triangles[t];
    const float b0 = 1.0f - b1 - b2;
    SurfacePoint sp;
    sp.p = barycentricPoint(scene_.positions[tri.v[0]], scene_.positions[tri.v[1]], scene_.positions[tri.v[2]], b1, b2);
    sp.ng = ng_[t];
    const Vec3& flat = flatNs_[t];
    sp.ns = flat.x != 0.0f || flat.y != 0.0f || flat.z != 0.0f ? flat : interpolatedNormal(tri, b0, b1, b2, sp.ng);
    sp.triangle = t;
    sp.material = tri.material;
    return sp;
  }

  uint64_t rayCount() const { return rays_.total(); }

  struct BarycentricAxes {
    Vec3 b1, b2;
  };

 private:
  struct ShadowRay;
  // The ray an occlusion query traces; false with `blocked` set when none is needed.
  bool shadowRay(const Segment& seg, ShadowRay& ray, bool& blocked) const;
  template <int K>
  void intersectPackets(const Ray* rays, int n, SurfacePoint* hits, float* distance, bool* found) const;
  template <int K>
  void occludedPackets(const Segment* segs, int n, bool* blocked) const;

  // The surface point of an Embree hit (u, v) at `distance` along the ray on quad primitive `quad`.
  // The barycentrics come from the hit position, not from Embree's (u, v): Embree's packet and
  // single-ray quad kernels round (u, v) differently, the distance they agree on.
  SurfacePoint hitPoint(uint32_t quad, float u, float v, const Vec3& origin, const Vec3& dir, float distance) const;
  // Unit shading normal interpolated from the vertex normals (the geometric one if degenerate).
  Vec3 interpolatedNormal(const Triangle& tri, float b0, float b1, float b2, const Vec3& ng) const;

  const Scene& scene_;
  RTCDevice device_ = nullptr;
  RTCScene rtcScene_ = nullptr;
  std::vector<QuadPrim> quads_;  // Embree's primitives: the scene's triangles in pairs
  std::vector<BarycentricAxes> baryAxes_;  // per triangle: barycentrics from a point in its plane
  std::vector<Vec3> ng_;
  std::vector<float> area_;
  std::vector<Vec3> flatNs_;  // unit shading normal of triangles whose vertex normals agree, else 0
  int packetWidth_ = 1;  // widest ray packet the Embree build runs natively (16, 8, 4; 1: none)
  float epsilonFloor_ = 1.0f;  // offsets never shrink below this scale: max(1, 1 % of the scene's extent)
  mutable PerWorkerCount rays_;  // traced from a rank's worker threads at once
};

}  // namespace relt
