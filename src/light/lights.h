#pragma once
// Emitters: every emissive triangle is an area light, every KHR_lights_punctual light a point or
// spot light. One light is picked per sample in proportion to its power.
#include <vector>

#include "core/math.h"
#include "core/sampling.h"
#include "scene/ray_tracer.h"

namespace relt {

struct Light {
  enum class Kind : uint8_t { Triangle, Point };
  Kind kind = Kind::Triangle;
  uint32_t index = 0;  // triangle id, or index into Scene::punctualLights
};

// A point on a light chosen for next-event estimation or as a light subpath origin.
struct LightPoint {
  uint32_t light = 0;     // index into LightSampler's light list
  SurfacePoint sp;        // position; normals meaningful for area lights only
  bool delta = false;     // punctual: position is a Dirac delta
  float pdfPick = 0.0f;   // probability of having picked this light
  float pdfPos = 0.0f;    // area density of the position (1 for punctual lights)
};

class LightSampler {
 public:
  LightSampler(const Scene& scene, const RayTracer& tracer);

  bool empty() const { return lights_.empty(); }
  size_t size() const { return lights_.size(); }
  const Light& light(uint32_t i) const { return lights_[i]; }

  // Pick a light by power and a position on it (u: one number for the pick, two for the position).
  // Inline, from a table of the emissive triangles: it runs at every path vertex.
  LightPoint samplePoint(float uPick, const Vec2& uPos) const {
    const uint32_t i = static_cast<uint32_t>(pick_.sample(uPick));
    if (i >= emitters_.size()) return samplePunctual(i);
    const TriangleEmitter& e = emitters_[i];
    LightPoint lp;
    lp.light = i;
    lp.pdfPick = e.pdfPick;
    lp.pdfPos = e.pdfPos;
    const Vec2 b = uniformTriangle(uPos);
    if (e.ns == Vec3(0.0f)) {
      lp.sp = tracer_.surfacePoint(e.triangle, b.x, b.y);
    } else {
      lp.sp.p = RayTracer::barycentricPoint(e.p[0], e.p[1], e.p[2], b.x, b.y);
      lp.sp.ng = e.ng;
      lp.sp.ns = e.ns;
      lp.sp.triangle = e.triangle;
      lp.sp.material = e.material;
    }
    return lp;
  }
  // Radiance leaving an area light point in direction w (zero on the back of one-sided emitters).
  Color emitted(const SurfacePoint& sp, const Vec3& w) const {
    const MaterialEmission& m = emission_[sp.material];
    if (!m.emissive || (!m.doubleSided && glm::dot(sp.ng, w) <= 0.0f)) return Color(0.0f);
    return m.radiance;
  }
  // Intensity of a punctual light in direction w (W/sr), including the spot falloff.
  Color intensity(uint32_t light, const Vec3& w) const;

  // Densities, for MIS: pick x position (area measure) of a given emissive triangle.
  float pdfPickTriangle(uint32_t triangle) const;
  float pdfPick(uint32_t light) const { return pick_.pmf(light); }
  float pdfPosition(uint32_t light) const;
  uint32_t lightOfTriangle(uint32_t triangle) const { return triangleLight_[triangle]; }

  // Emission direction from a light point, and its solid-angle density.
  struct Emission {
    Vec3 dir;
    float pdfDir = 0.0f;
  };
  Emission sampleDirection(const LightPoint& lp, const Vec2& u) const;
  float pdfDirection(uint32_t light, const SurfacePoint& sp, const Vec3& w) const;

 private:
  // What sampling a point on an emissive triangle needs, without lookups through the scene.
  struct TriangleEmitter {
    Vec3 p[3];
    Vec3 ng;
    Vec3 ns;  // the triangle's constant shading normal; zero where it varies over the triangle
    uint32_t triangle = 0, material = 0;
    float pdfPick = 0.0f, pdfPos = 0.0f;
  };
  struct MaterialEmission {
    Color radiance{0.0f};
    bool emissive = false, doubleSided = false;
  };
  LightPoint samplePunctual(uint32_t light) const;

  const Scene& scene_;
  const RayTracer& tracer_;
  std::vector<Light> lights_;  // the emissive triangles first, then the punctual lights
  std::vector<TriangleEmitter> emitters_;  // lights_[i] for i < emitters_.size()
  std::vector<MaterialEmission> emission_;  // per material
  std::vector<uint32_t> triangleLight_;  // triangle -> light index (UINT32_MAX if not emissive)
  Distribution1D pick_;
};

}  // namespace relt
