// The camera subpath of VCM and the techniques taken at its vertices (vcm_tracer.h).
#include <cmath>
#include <limits>

#include "path/vertex.h"
#include "vcm/vcm_tracer.h"

namespace relt {

void VcmTracer::traceCameraPath(const Vec2& film, SampleSource& u, std::span<const LightVertex> own,
                                std::span<const LightVertex> all, const HashGrid* grid, PathSample& out) const {
  VcmSubpath s;
  s.dir = ctx_.camera.direction(film);
  const float pdfCamera = ctx_.camera.pdfDirection(s.dir);
  if (!(pdfCamera > 0.0f)) return;
  s.dVCM = mis(1.0f / pdfCamera);  // N_L / (the pixel's density): one light subpath per camera sample
  s.origin = s.last = ctx_.camera.position();
  const int maxDepth = ctx_.settings.maxDepth;
  while (true) {
    SurfacePoint hit;
    const Vec3 from = s.last;
    if (!arrive(s, hit)) return;
    const Vec3 wo = glm::normalize(from - hit.p);
    const Color le = ctx_.lights.emitted(hit, wo);
    if (!isBlack(le)) out.add(film, s.beta * le * emissionWeight(s, hit, wo), s.specular ? PathClass::L0 : PathClass::L1);
    if (s.length >= maxDepth) return;
    const Bsdf bsdf(ctx_.scene.materials[hit.material], hit.ns, hit.ng);
    if (!bsdf.isDelta()) {
      Color sum(0.0f);
      if (connects()) {
        sum += nextEvent(s, hit, wo, bsdf, u);
        for (const LightVertex& y : own)
          if (y.length + s.length + 1 <= maxDepth) sum += connect(s, hit, wo, bsdf, y);
      }
      if (merges() && grid) sum += merge(s, hit, wo, bsdf, all, *grid);
      out.add(film, sum, PathClass::L5);
      if (iteration_.mode == VcmMode::Ppm) return;  // merged at its first non-specular vertex
    }
    if (!scatter(bsdf, hit, wo, TransportMode::Radiance, u, SampleStream::Camera, s)) return;
  }
}

// s = 0: the camera subpath found an emitter. Seen straight from the pinhole, only this technique
// makes the path; with merging only, every path through a non-specular vertex is merged instead.
float VcmTracer::emissionWeight(const VcmSubpath& s, const SurfacePoint& hit, const Vec3& wo) const {
  if (s.length == 1) return 1.0f;
  if (iteration_.mode == VcmMode::Ppm) return s.specular ? 1.0f : 0.0f;
  const uint32_t light = ctx_.lights.lightOfTriangle(hit.triangle);
  if (light == std::numeric_limits<uint32_t>::max()) return 0.0f;
  const float pdfStart = ctx_.lights.pdfPick(light) * ctx_.lights.pdfPosition(light);
  const float pdfEmit = pdfStart * ctx_.lights.pdfDirection(light, hit, wo);
  return 1.0f / (1.0f + mis(pdfStart) * s.dVCM + mis(pdfEmit) * s.dVC);
}

// s = 1: a point on a light sampled for camera vertex x.
Color VcmTracer::nextEvent(const VcmSubpath& s, const SurfacePoint& x, const Vec3& wo, const Bsdf& bsdf,
                           SampleSource& u) const {
  const float uPick = u.next(SampleStream::Connection);
  const Vec2 uPos = u.next2(SampleStream::Connection);
  if (s.length + 1 > ctx_.settings.maxDepth || ctx_.lights.empty()) return Color(0.0f);
  const LightPoint lp = ctx_.lights.samplePoint(uPick, uPos);
  const Vec3 d = lp.sp.p - x.p;
  const float dist2 = glm::dot(d, d);
  if (!(dist2 > 0.0f)) return Color(0.0f);
  const Vec3 w = d / std::sqrt(dist2);
  const Color le = lp.delta ? ctx_.lights.intensity(lp.light, -w) : ctx_.lights.emitted(lp.sp, -w);
  const float cosAtLight = lp.delta ? 1.0f : std::abs(glm::dot(lp.sp.ng, w));
  const Color f = bsdf.eval(wo, w, TransportMode::Radiance);
  if (isBlack(le) || isBlack(f) || !(cosAtLight > 0.0f)) return Color(0.0f);
  const float q = continuationProbability(bsdf.material());
  const float pdfLightW = lp.pdfPick * lp.pdfPos * dist2 / cosAtLight;  // the light point's, seen from x
  const float pdfHitW = lp.delta ? 0.0f : bsdf.pdf(wo, w) * q;          // the camera subpath hitting it
  const float pdfEmitA = ctx_.lights.pdfDirection(lp.light, lp.sp, -w) * std::abs(glm::dot(x.ng, w)) / dist2;
  const float wLight = mis(pdfHitW / pdfLightW);
  const float wCamera = mis(pdfEmitA) * (vmWeight_ + s.dVCM + s.dVC * mis(bsdf.pdf(w, wo) * q));
  const bool blocked = lp.delta ? ctx_.tracer.occludedToPoint(x.p, x.ng, lp.sp.p)
                                : ctx_.tracer.occluded(x.p, x.ng, lp.sp.p, lp.sp.ng);
  if (blocked) return Color(0.0f);
  return s.beta * f * le * (std::abs(glm::dot(x.ns, w)) / pdfLightW / (wLight + 1.0f + wCamera));
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
  const Bsdf light(ctx_.scene.materials[y.sp.material], y.sp.ns, y.sp.ng);
  const Color fL = light.eval(y.wo, -w, TransportMode::Importance) * shadingCorrection(y.sp, y.wo, -w);
  if (isBlack(fL)) return Color(0.0f);
  const float qC = continuationProbability(bsdf.material()), qL = continuationProbability(light.material());
  const float cameraPdfA = bsdf.pdf(wo, w) * qC * std::abs(glm::dot(y.sp.ng, w)) / dist2;
  const float lightPdfA = light.pdf(y.wo, -w) * qL * std::abs(glm::dot(x.ng, w)) / dist2;
  const float wLight = mis(cameraPdfA) * (vmWeight_ + y.dVCM + y.dVC * mis(light.pdf(-w, y.wo) * qL));
  const float wCamera = mis(lightPdfA) * (vmWeight_ + s.dVCM + s.dVC * mis(bsdf.pdf(w, wo) * qC));
  if (ctx_.tracer.occluded(x.p, x.ng, y.sp.p, y.sp.ng)) return Color(0.0f);
  const float g = std::abs(glm::dot(x.ns, w)) * std::abs(glm::dot(y.sp.ns, w)) / dist2;
  return s.beta * fC * fL * y.beta * (g / (wLight + 1.0f + wCamera));
}

// Vertex merging: the light vertices within r of x, as if x's subpath had reached each of them.
Color VcmTracer::merge(const VcmSubpath& s, const SurfacePoint& x, const Vec3& wo, const Bsdf& bsdf,
                       std::span<const LightVertex> all, const HashGrid& grid) const {
  Color sum(0.0f);
  const float qC = continuationProbability(bsdf.material());
  const bool weighted = iteration_.mode != VcmMode::Ppm;
  grid.forEachNear(x.p, [&](uint32_t i) {
    const LightVertex& y = all[i];
    if (y.length + s.length > ctx_.settings.maxDepth) return;
    const Color f = bsdf.eval(wo, y.wo, TransportMode::Radiance);
    if (isBlack(f)) return;
    float weight = 1.0f;
    if (weighted) {
      const float qL = continuationProbability(ctx_.scene.materials[y.sp.material]);
      const float wLight = y.dVCM * vcWeight_ + y.dVM * mis(bsdf.pdf(wo, y.wo) * qC);
      const float wCamera = s.dVCM * vcWeight_ + s.dVM * mis(bsdf.pdf(y.wo, wo) * qL);
      weight = 1.0f / (wLight + 1.0f + wCamera);
    }
    sum += f * y.beta * weight;
  });
  return s.beta * sum * float(mergeNormalisation_);
}

}  // namespace relt
