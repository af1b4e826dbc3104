// The camera subpath of VCM and the techniques taken at its vertices (vcm_tracer.h).
#include <cmath>

#include "path/vertex.h"
#include "vcm/vcm_tracer.h"

namespace relt {

void VcmTracer::traceCameraPath(const Vec2& film, SampleSource& u, std::span<const LightVertex> own,
                                std::span<const LightVertex> bySlot, const HashGrid* grid,
                                PathSample& out) const {
  const int maxDepth = ctx_.settings.maxDepth;
  const auto onEmitter = [&](const VcmSubpath& s, const SurfacePoint& hit, const Vec3& wo, const Color& le) {
    out.add(film, s.beta * le * mis_.emissionWeight(s, hit, wo), s.specular ? PathClass::L0 : PathClass::L1);
  };
  const auto onSurface = [&](const VcmSubpath& s, const SurfacePoint& hit, const Vec3& wo, const Bsdf& bsdf) {
    Color sum(0.0f);
    if (mis_.connects()) {
      const WeightedLater nee = nextEventLater(s, hit, wo, bsdf, u);
      sum += nee.value * nee.weight.weight(mis_.lightSubpathTerm());
      for (const LightVertex& y : own)
        if (y.length + s.length + 1 <= maxDepth) sum += connect(s, hit, wo, bsdf, y);
    }
    if (mis_.merges() && grid) sum += merge(s, hit, wo, bsdf, bySlot, *grid);
    out.add(film, sum, PathClass::L5);
    return mis_.mode() != VcmMode::Ppm;  // merging only: merged at its first non-specular vertex
  };
  walkCamera(film, u, onEmitter, onSurface);
}

// s = 1: a point on a light sampled for camera vertex x.
WeightedLater VcmTracer::nextEventLater(const VcmSubpath& s, const SurfacePoint& x, const Vec3& wo, const Bsdf& bsdf,
                                        SampleSource& u) const {
  const float uPick = u.next(SampleStream::Connection);
  const Vec2 uPos = u.next2(SampleStream::Connection);
  if (s.length + 1 > ctx_.settings.maxDepth || ctx_.lights.empty()) return {};
  const LightPoint lp = ctx_.lights.samplePoint(uPick, uPos);
  const Vec3 d = lp.sp.p - x.p;
  const float dist2 = glm::dot(d, d);
  if (!(dist2 > 0.0f)) return {};
  const Vec3 w = d / std::sqrt(dist2);
  const Color le = lp.delta ? ctx_.lights.intensity(lp.light, -w) : ctx_.lights.emitted(lp.sp, -w);
  const float cosAtLight = lp.delta ? 1.0f : std::abs(glm::dot(lp.sp.ng, w));
  const Color f = bsdf.eval(wo, w, TransportMode::Radiance);
  if (isBlack(le) || isBlack(f) || !(cosAtLight > 0.0f)) return {};
  const bool blocked = lp.delta ? ctx_.tracer.occludedToPoint(x.p, x.ng, lp.sp.p)
                                : ctx_.tracer.occluded(x.p, x.ng, lp.sp.p, lp.sp.ng);
  if (blocked) return {};
  const float pdfLightW = lp.pdfPick * lp.pdfPos * dist2 / cosAtLight;  // the light point's, seen from x
  return {s.beta * f * le * (std::abs(glm::dot(x.ns, w)) / pdfLightW), mis_.nextEventWeightParts(s, x, wo, bsdf, lp)};
}

// s >= 2, t >= 2: camera vertex x joined to light vertex y.
Color VcmTracer::connect(const VcmSubpath& s, const SurfacePoint& x, const Vec3& wo, const Bsdf& bsdf,
                         const LightVertex& y) const {
  const Vec3 d = y.sp.p - x.p;
  const float dist2 = glm::dot(d, d);
  if (!(dist2 > 0.0f)) return Color(0.0f);
  const Vec3 w = d / std::sqrt(dist2);
  const Color fC = bsdf.eval(wo, w, TransportMode::Radiance);
  if (isBlack(fC)) return Color(0.0f);
  const Bsdf atY(ctx_.scene.materials[y.sp.material], y.sp.ns, y.sp.ng);
  const Color fL = atY.eval(y.wo, -w, TransportMode::Importance) * shadingCorrection(y.sp, y.wo, -w);
  if (isBlack(fL) || ctx_.tracer.occluded(x.p, x.ng, y.sp.p, y.sp.ng)) return Color(0.0f);
  const float g = std::abs(glm::dot(x.ns, w)) * std::abs(glm::dot(y.sp.ns, w)) / dist2;
  return s.beta * fC * fL * y.beta * (g * mis_.connectWeight(s, x, wo, bsdf, y, atY));
}

// Vertex merging: the light vertices within r of x, as if x's subpath had reached each of them.
Color VcmTracer::merge(const VcmSubpath& s, const SurfacePoint& x, const Vec3& wo, const Bsdf& bsdf,
                       std::span<const LightVertex> bySlot, const HashGrid& grid) const {
  Color sum(0.0f);
  uint64_t merged = 0;
  grid.forEachSlotNear(x.p, [&](uint32_t slot) {
    const LightVertex& y = bySlot[slot];
    if (y.length + s.length > ctx_.settings.maxDepth) return;
    ++merged;
    sum += mergeOne(s, wo, bsdf, y);
  });
  if (merges_ && merged) merges_->add(merged);
  return s.beta * sum * float(mis_.mergeNormalisation());
}

Color VcmTracer::mergeOne(const VcmSubpath& s, const Vec3& wo, const Bsdf& bsdf, const LightVertex& y) const {
  const Color f = bsdf.eval(wo, y.wo, TransportMode::Radiance);
  return isBlack(f) ? Color(0.0f) : f * y.beta * mis_.mergeWeight(s, wo, bsdf, y);
}

}  // namespace relt
