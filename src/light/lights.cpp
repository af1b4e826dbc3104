#include "light/lights.h"

#include <limits>

namespace relt {
namespace {

constexpr uint32_t kNoLight = std::numeric_limits<uint32_t>::max();

// glTF KHR_lights_punctual spot attenuation: smooth in the cosine between the two cone angles.
float spotFalloff(const PunctualLight& l, const Vec3& w) {
  if (!l.spot) return 1.0f;
  const float cd = glm::dot(l.direction, w);
  if (cd <= l.cosOuter) return 0.0f;
  if (cd >= l.cosInner) return 1.0f;
  const float x = (cd - l.cosOuter) / std::max(1e-6f, l.cosInner - l.cosOuter);
  return x * x;
}

}  // namespace

LightSampler::LightSampler(const Scene& scene, const RayTracer& tracer)
    : scene_(scene), tracer_(tracer), triangleLight_(scene.triangles.size(), kNoLight) {
  std::vector<double> power;
  for (uint32_t t = 0; t < scene.triangles.size(); ++t) {
    const Material& m = scene.materials[scene.triangles[t].material];
    if (!m.isEmissive() || tracer.triangleArea(t) <= 0.0f) continue;
    triangleLight_[t] = static_cast<uint32_t>(lights_.size());
    lights_.push_back({Light::Kind::Triangle, t});
    // Lambertian emitter: power = pi * area * L (twice for two-sided emitters).
    power.push_back(kPi * tracer.triangleArea(t) * luminance(m.emission) * (m.doubleSided ? 2.0 : 1.0));
  }
  for (uint32_t i = 0; i < scene.punctualLights.size(); ++i) {
    const PunctualLight& l = scene.punctualLights[i];
    if (isBlack(l.intensity)) continue;
    lights_.push_back({Light::Kind::Point, i});
    // Integral of spotFalloff over the sphere: full inside the inner cone, quadratic ramp to the outer.
    const double solidAngle =
        l.spot ? 2.0 * kPi * ((1.0 - l.cosInner) + (l.cosInner - l.cosOuter) / 3.0) : 4.0 * kPi;
    power.push_back(solidAngle * luminance(l.intensity));
  }
  pick_ = Distribution1D(power);

  for (uint32_t i = 0; i < lights_.size() && lights_[i].kind == Light::Kind::Triangle; ++i) {
    const uint32_t t = lights_[i].index;
    const Triangle& tri = scene.triangles[t];
    TriangleEmitter e;
    for (int k = 0; k < 3; ++k) e.p[k] = scene.positions[tri.v[k]];
    e.ng = tracer.triangleNormal(t);
    e.ns = tracer.flatShadingNormal(t);
    e.triangle = t;
    e.material = tri.material;
    e.pdfPick = pick_.pmf(i);
    e.pdfPos = 1.0f / tracer.triangleArea(t);
    emitters_.push_back(e);
  }
  for (const Material& m : scene.materials) emission_.push_back({m.emission, m.isEmissive(), m.doubleSided});
}

LightPoint LightSampler::samplePunctual(uint32_t light) const {
  LightPoint lp;
  lp.light = light;
  lp.pdfPick = pick_.pmf(light);
  const PunctualLight& pl = scene_.punctualLights[lights_[light].index];
  lp.sp.p = pl.position;
  lp.sp.ng = lp.sp.ns = pl.spot ? pl.direction : Vec3(0, 0, 1);
  lp.delta = true;
  lp.pdfPos = 1.0f;
  return lp;
}

Color LightSampler::intensity(uint32_t light, const Vec3& w) const {
  const PunctualLight& pl = scene_.punctualLights[lights_[light].index];
  return pl.intensity * spotFalloff(pl, w);
}

float LightSampler::pdfPickTriangle(uint32_t triangle) const {
  const uint32_t l = triangleLight_[triangle];
  return l == kNoLight ? 0.0f : pick_.pmf(l);
}

float LightSampler::pdfPosition(uint32_t light) const {
  const Light& l = lights_[light];
  return l.kind == Light::Kind::Triangle ? 1.0f / tracer_.triangleArea(l.index) : 1.0f;
}

LightSampler::Emission LightSampler::sampleDirection(const LightPoint& lp, const Vec2& u) const {
  const Light& l = lights_[lp.light];
  Emission e;
  if (l.kind == Light::Kind::Triangle) {
    const Material& m = scene_.materials[lp.sp.material];
    Vec2 uu = u;
    Vec3 n = lp.sp.ng;
    if (m.doubleSided) {
      // Pick a side with probability 1/2 and reuse the number.
      if (uu.x < 0.5f) {
        uu.x *= 2.0f;
      } else {
        uu.x = (uu.x - 0.5f) * 2.0f;
        n = -n;
      }
    }
    const Vec3 local = cosineHemisphere(glm::min(uu, Vec2(0x1.fffffep-1f)));
    e.dir = glm::normalize(Frame(n).toWorld(local));
    e.pdfDir = cosineHemispherePdf(local.z) * (m.doubleSided ? 0.5f : 1.0f);
  } else {
    const PunctualLight& pl = scene_.punctualLights[l.index];
    if (pl.spot) {
      e.dir = glm::normalize(Frame(pl.direction).toWorld(uniformCone(u, pl.cosOuter)));
      e.pdfDir = 1.0f / (2.0f * kPi * (1.0f - pl.cosOuter));
    } else {
      e.dir = uniformSphere(u);
      e.pdfDir = kInv4Pi;
    }
  }
  return e;
}

float LightSampler::pdfDirection(uint32_t light, const SurfacePoint& sp, const Vec3& w) const {
  const Light& l = lights_[light];
  if (l.kind == Light::Kind::Triangle) {
    const Material& m = scene_.materials[scene_.triangles[l.index].material];
    const float c = glm::dot(sp.ng, w);
    if (m.doubleSided) return 0.5f * std::abs(c) * kInvPi;
    return c > 0.0f ? c * kInvPi : 0.0f;
  }
  const PunctualLight& pl = scene_.punctualLights[l.index];
  if (pl.spot) return glm::dot(pl.direction, w) > pl.cosOuter ? 1.0f / (2.0f * kPi * (1.0f - pl.cosOuter)) : 0.0f;
  return kInv4Pi;
}

}  // namespace relt
